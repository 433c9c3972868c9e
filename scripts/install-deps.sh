#!/usr/bin/env bash
# Installs what granbond needs on a fresh Debian machine and is a no-op when
# it is all there: the Rust toolchain must exist (rustup's cargo); Python
# plotting packages come from PyPI.
set -euo pipefail
if ! command -v cargo >/dev/null 2>&1; then
    echo "install-deps: cargo not found; install Rust (https://rustup.rs) first" >&2
    exit 1
fi
# Debian packages: compilers, CMake, the stock LIGGGHTS 3.8 (engine,
# headers, MPI) that the adapter in cpp-adapter/liggghts is built against,
# and the stock LAMMPS (29 Sep 2021; `lmp`, liblammps-dev) for
# cpp-adapter/lammps (dpkg-dev: `apt-get source` fetches the headers
# liblammps-dev lacks, see cmake/fetch_lammps_headers.sh).
apt_packages="gcc g++ make cmake python3 liggghts libliggghts-dev libopenmpi-dev openmpi-bin"
apt_packages="$apt_packages lammps liblammps-dev dpkg-dev xz-utils"
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
