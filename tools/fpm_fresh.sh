#!/usr/bin/env bash
# fpm 0.12 does not always rebuild what depends on a changed module (we saw a test object
# keep an old derived-type layout and a program not relinked after library changes). When
# any Fortran/C source is newer than the last build, drop fpm's build trees so the next fpm
# command rebuilds from scratch (about a minute); otherwise do nothing.
set -euo pipefail
cd "$(dirname "$0")/.."
stamp=build/.fpm-sources-stamp
if [[ -f $stamp ]] && [[ -z $(find src app test bench fpm.toml -newer "$stamp" \
     \( -name '*.f90' -o -name '*.c' -o -name '*.toml' \) -print -quit 2>/dev/null) ]]; then
  exit 0
fi
rm -rf build/gfortran_*
mkdir -p build
touch "$stamp"
