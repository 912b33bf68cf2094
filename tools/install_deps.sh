#!/usr/bin/env bash
# Checks that everything PECPLAS needs to build and test is on this machine (Debian 12), and
# installs what is missing when run as root; otherwise prints the commands and exits 1.
#   tools/install_deps.sh            check, install as root
#   tools/install_deps.sh --check    check only (exit 1 when something is missing)
#   PECPLAS_MPI=1 tools/install_deps.sh   also OpenMPI and MUMPS, for the MPI build
#                                         (make build-mpi, doc/mpi.md); never otherwise
# Optional Python packages (OPTIONAL_PIP_PACKAGES: gmsh, which meshes the examples of
# doc/gmsh.md and their test; pytest-xdist, with which make test runs the Python tests on
# two workers) are installed as root when missing, on a best-effort basis; their absence is
# never an error (the tests that need gmsh are skipped, saying why; without pytest-xdist the
# Python tests run one at a time).
# Quiet and fast when all is present: cheap file and PATH tests, one python start-up.
# Runs unattended (CI=true, no stdin): apt-get -y with DEBIAN_FRONTEND=noninteractive.
set -euo pipefail

APT_PACKAGES=(gfortran libhdf5-dev libsuitesparse-dev libopenblas-dev liblapack-dev pkg-config cmake)
MPI_APT_PACKAGES=(libmumps-dev libopenmpi-dev openmpi-bin)
if [[ ${PECPLAS_MPI:-0} == 1 ]]; then APT_PACKAGES+=("${MPI_APT_PACKAGES[@]}"); fi
PIP_PACKAGES=(fpm numpy h5py matplotlib pytest)
OPTIONAL_PIP_PACKAGES=(gmsh pytest-xdist)
PYTHON=${PYTHON:-python3}
export DEBIAN_FRONTEND=noninteractive

mode=install
case "${1:-}" in
  --check) mode=check ;;
  "") ;;
  *) echo "usage: $0 [--check]" >&2; exit 2 ;;
esac

# Python facts in one start-up: scripts dir (where `pip install fpm` puts fpm), user base,
# whether pip refuses system installs (PEP 668), and which modules are missing.
py_facts() {
  "$PYTHON" - <<'EOF' 2>/dev/null
import importlib.util, os, site, sysconfig
print(sysconfig.get_path("scripts"))
print(site.getuserbase())
marker = os.path.join(sysconfig.get_path("stdlib"), "EXTERNALLY-MANAGED")
print("managed" if os.path.exists(marker) else "free")
print(" ".join(m for m in ("numpy", "h5py", "matplotlib", "pytest")
               if importlib.util.find_spec(m) is None))
print(" ".join(p for m, p in (("gmsh", "gmsh"), ("xdist", "pytest-xdist"))
               if importlib.util.find_spec(m) is None))
EOF
}

# Directories where the linker finds system libraries on Debian and elsewhere.
lib_dirs=(/usr/lib/*-linux-gnu /usr/lib64 /usr/lib /usr/local/lib)
have_lib() {  # have_lib NAME...: true when any libNAME.so (or .a) exists
  local name dir
  for name in "$@"; do
    for dir in "${lib_dirs[@]}"; do
      [[ -e $dir/lib$name.so || -e $dir/lib$name.a ]] && return 0
    done
  done
  return 1
}
have_header() {  # have_header FILE: in a system include dir or its suitesparse/ subdir
  local dir
  for dir in /usr/include /usr/local/include; do
    [[ -e $dir/$1 || -e $dir/suitesparse/$1 ]] && return 0
  done
  return 1
}

missing_apt=()
missing_pip=()
missing_optional=()
pip_flags=()

check() {
  missing_apt=()
  missing_pip=()
  command -v gfortran >/dev/null || missing_apt+=("gfortran (Fortran compiler)")
  command -v cmake >/dev/null && command -v ctest >/dev/null || missing_apt+=("cmake")
  if ! command -v pkg-config >/dev/null; then
    missing_apt+=("pkg-config")
  elif ! pkg-config --exists hdf5; then
    missing_apt+=("HDF5 (pkg-config hdf5)")
  else
    # Debian's hdf5.pc has no libdir/includedir variables: read its -I and -L flags.
    local flag found_mod=no found_lib=no
    for flag in $(pkg-config --cflags-only-I hdf5) -I/usr/include; do
      [[ -e ${flag#-I}/hdf5.mod ]] && found_mod=yes
    done
    for flag in $(pkg-config --libs-only-L hdf5); do
      compgen -G "${flag#-L}/libhdf5*_fortran.so" >/dev/null && found_lib=yes
    done
    [[ $found_lib == yes ]] || have_lib hdf5_fortran hdf5_serial_fortran \
      || missing_apt+=("HDF5 Fortran library (libhdf5_fortran)")
    [[ $found_mod == yes ]] || missing_apt+=("HDF5 Fortran module hdf5.mod")
  fi
  have_header cholmod.h && have_header umfpack.h || missing_apt+=("SuiteSparse headers")
  have_lib cholmod && have_lib umfpack && have_lib suitesparseconfig \
    || missing_apt+=("SuiteSparse libraries (cholmod, umfpack)")
  have_lib lapack || missing_apt+=("LAPACK")
  if [[ ${PECPLAS_MPI:-0} == 1 ]]; then
    have_header dmumps_c.h && have_lib dmumps mumps_common || missing_apt+=("MUMPS (libmumps-dev)")
    command -v mpirun >/dev/null && command -v mpicc >/dev/null \
      || missing_apt+=("OpenMPI (libopenmpi-dev, openmpi-bin)")
  fi
  have_lib blas openblas || missing_apt+=("BLAS")

  local facts=()
  if command -v "$PYTHON" >/dev/null; then
    mapfile -t facts < <(py_facts)
  fi
  if ((${#facts[@]} < 3)); then
    missing_apt+=("$PYTHON")
    missing_pip=("${PIP_PACKAGES[@]}")
    return
  fi
  # fpm from pip may be only in the interpreter's scripts dir or the user base (no pyenv
  # rehash yet): look there as the Makefile does.
  PATH="${facts[0]}:$PATH:${facts[1]}/bin"
  pip_flags=()
  if [[ ${facts[2]} == managed ]]; then  # Debian's own python3: root installs system-wide
    pip_flags=(--break-system-packages)
    [[ $(id -u) -eq 0 ]] || pip_flags+=(--user)
  fi
  command -v fpm >/dev/null && fpm --version >/dev/null 2>&1 || missing_pip+=(fpm)
  if [[ -n ${facts[3]:-} ]]; then
    read -r -a mods <<<"${facts[3]}"
    missing_pip+=("${mods[@]}")
  fi
  missing_optional=()
  if [[ -n ${facts[4]:-} ]]; then
    read -r -a mods <<<"${facts[4]}"
    missing_optional+=("${mods[@]}")
  fi
}

optional() {  # the optional packages: installed as root (one try), else a note
  ((${#missing_optional[@]})) || return 0
  if [[ $mode == install && $(id -u) -eq 0 ]]; then
    echo "install_deps: + optional: $PYTHON -m pip install ${missing_optional[*]}"
    "$PYTHON" -m pip install --disable-pip-version-check "${pip_flags[@]}" \
      --root-user-action=ignore -q "${missing_optional[@]}" </dev/null \
      || echo "install_deps: optional ${missing_optional[*]} not installed (tests that need it are skipped)" >&2
  else
    echo "install_deps: optional, not installed: ${missing_optional[*]} (pip install ${missing_optional[*]}: doc/build.md)" >&2
  fi
}

retry() {  # retry CMD...: three tries, for a registry that hiccups
  local n
  for n in 1 2 3; do
    "$@" && return 0
    echo "install_deps: '$*' failed (try $n of 3)" >&2
    sleep $((n * 5))
  done
  return 1
}

check
if ((${#missing_apt[@]} == 0 && ${#missing_pip[@]} == 0)); then
  echo "install_deps: all build and test dependencies present"
  optional
  exit 0
fi

echo "install_deps: missing:"
for item in "${missing_apt[@]}" "${missing_pip[@]}"; do
  [[ -n $item ]] && echo "  - $item"
done

apt_cmd=(apt-get install -y --no-install-recommends "${APT_PACKAGES[@]}")
command -v "$PYTHON" >/dev/null || apt_cmd+=(python3 python3-pip)
pip_command() {  # after check(): the pip line for this interpreter
  pip_cmd=("$PYTHON" -m pip install --disable-pip-version-check "${pip_flags[@]}" "${PIP_PACKAGES[@]}")
}
pip_command

if [[ $mode == check || $(id -u) -ne 0 ]]; then
  echo "install_deps: run these (as root, or with sudo), then retry:" >&2
  if ((${#missing_apt[@]})); then
    echo "  sudo apt-get update && sudo ${apt_cmd[*]}" >&2
  fi
  echo "  ${pip_cmd[*]}" >&2
  exit 1
fi

if ((${#missing_apt[@]})); then
  echo "install_deps: + apt-get update && ${apt_cmd[*]}"
  retry apt-get update -qq
  retry "${apt_cmd[@]}" -q </dev/null
  check  # a Python installed just now decides the pip flags
  pip_command
fi
if ((${#missing_pip[@]})); then
  # pip as root is intended here (CI, a fresh machine); its warning about that is noise.
  echo "install_deps: + ${pip_cmd[*]}"
  retry "${pip_cmd[@]}" --root-user-action=ignore -q </dev/null
  if command -v pyenv >/dev/null; then pyenv rehash || true; fi
fi

check
if ((${#missing_apt[@]} || ${#missing_pip[@]})); then
  echo "install_deps: still missing after install: ${missing_apt[*]} ${missing_pip[*]}" >&2
  exit 1
fi
optional
echo "install_deps: done, all build and test dependencies present"
