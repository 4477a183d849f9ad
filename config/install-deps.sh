#!/usr/bin/env bash
# Installs the system packages hylc needs on Debian/Ubuntu, only those that are missing.
# Does nothing (quickly) when everything is present.  Needs root or sudo to install.
#   HYLC_NO_INSTALL=1  only check, never install
#   HYLC_DEPS_EXTRA="pkg ..."  also these (make fuzz: clang-14 libclang-rt-14-dev)
set -eu
pkgs=(petsc-dev libopenmpi-dev openmpi-bin libhdf5-openmpi-dev libmetis-dev nettle-dev libyaml-dev hdf5-tools pkg-config make gcc valgrind lcov python3-h5py python3-matplotlib python3-scipy ${HYLC_DEPS_EXTRA:-})
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

if ! command -v apt-get >/dev/null 2>&1; then
  echo "install-deps: missing packages (${missing[*]}) and no apt-get on this machine;" >&2
  echo "install PETSc (with HDF5 and MPI), Open MPI, HDF5 (openmpi flavour) and METIS by hand." >&2
  exit 1
fi
if [ "${HYLC_NO_INSTALL:-0}" = 1 ]; then
  echo "install-deps: missing packages: ${missing[*]} (HYLC_NO_INSTALL=1: not installing)" >&2
  exit 1
fi
if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "install-deps: missing packages (${missing[*]}); run as root or install sudo" >&2
  exit 1
fi
echo "install-deps: installing ${missing[*]}"
"${sudo[@]}" apt-get update -q
DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}" 2>&1 |
  grep -v 'no alternatives for petsc' || true
for p in "${missing[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' ||
    { echo "install-deps: $p failed to install" >&2; exit 1; }
done
echo "install-deps: done"
