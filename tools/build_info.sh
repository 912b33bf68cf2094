#!/usr/bin/env bash
# Writes src/base/provenance_commit.h (git-ignored) with the commit `pecplas --version` reports:
# `git describe --always --dirty`, or "unknown" outside a git checkout. The file is rewritten
# only when the commit changed, so an unchanged tree does not recompile. fpm does not track C
# headers, so the shim's objects in fpm's build trees are deleted then: fpm recompiles a missing
# object and relinks. Called by the Makefile before fpm builds; CMake has its own
# (cmake/BuildInfo.cmake).
set -euo pipefail
cd "$(dirname "$0")/.."
commit=$(git describe --always --dirty --tags 2>/dev/null || echo unknown)
header=src/base/provenance_commit.h
line="#define PECPLAS_COMMIT \"$commit\""
if [[ ! -f $header ]] || [[ $(cat "$header") != "$line" ]]; then
  printf '%s\n' "$line" >"$header"
  rm -f build/gfortran_*/pecplas/src_pecplas_provenance_shim.c.o
fi
