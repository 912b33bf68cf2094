#!/usr/bin/env bash
# `make install PREFIX=DIR` (default ~/.local): builds the release profile with fpm and puts
# pecplas, pecplas-path, pecplas-identify, pecplas-sensitivity, pecplas-sweep, pecplas-plot and
# pecplas-slope (the Python sweep, picture and limit-equilibrium tools,
# tools/pecplas_py/programs/pecplas_{sweep,plot,slope}.py, each stand-alone) into DIR/bin. fpm install
# would also install the benchmark programs, so it installs into a staging directory and only
# the four are copied.
set -euo pipefail
cd "$(dirname "$0")/.."
prefix=${1:-$HOME/.local}
FPM=${FPM:-fpm}
PROGRAMS=(pecplas pecplas-path pecplas-identify pecplas-sensitivity)
bash tools/build_info.sh
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
"$FPM" install --profile release --prefix "$stage" >/dev/null
mkdir -p "$prefix/bin"
for p in "${PROGRAMS[@]}"; do
  install -m 755 "$stage/bin/$p" "$prefix/bin/$p"
done
install -m 755 tools/pecplas_py/programs/pecplas_sweep.py "$prefix/bin/pecplas-sweep"
install -m 755 tools/pecplas_py/programs/pecplas_plot.py "$prefix/bin/pecplas-plot"
install -m 755 tools/pecplas_py/programs/pecplas_slope.py "$prefix/bin/pecplas-slope"
echo "installed into $prefix/bin: ${PROGRAMS[*]} pecplas-sweep pecplas-plot pecplas-slope"
case ":$PATH:" in
  *":$prefix/bin:"*) ;;
  *) echo "note: $prefix/bin is not on PATH (add: export PATH=\"$prefix/bin:\$PATH\")" ;;
esac
