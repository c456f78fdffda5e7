#!/usr/bin/env bash
# Installs the Debian packages this project builds and runs with.
# Idempotent: when every package is already installed it does nothing (no apt call).
# Works as root on a bare Debian 12 machine; as another user it uses sudo.
set -euo pipefail

packages=(
  # toolchain
  g++ make cmake ccache binutils
  # rfm/ (dense linear algebra), problem files, command line
  libeigen3-dev nlohmann-json3-dev libcli11-dev libfmt-dev
  # fem_reference/: deal.II 9.4 (MPI, p4est, PETSc, Trilinos, UMFPACK, gmsh) and gmsh itself
  libdeal.ii-dev gmsh libgmsh-dev
  # mpirun for fem_solve's distributed runs and the `mpi` tests (deal.II's MPI is Open MPI)
  openmpi-bin
  # faster BLAS for UMFPACK than Debian's reference BLAS
  libopenblas0-pthread
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # report figures (Debian's /usr/bin/python3)
  python3 python3-numpy python3-matplotlib
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} Debian packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: not root and no sudo: install ${missing[*]} by hand" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
echo "setup: done"
