#!/bin/sh
# localize_core.sh IN OUT
#
# OUT: the cargo-built archive IN as one relocatable object, holding only
# what the C ABI (granbond_*) reaches, with no debug information, and with
# granbond_* as its only global symbols. The Rust std inside the archive
# then cannot clash with another Rust library a program links, and a user
# linking the archive statically gets the core's code, not all of std.
#
# Does nothing when OUT is newer than IN and this script, so that the
# programs linking OUT are not relinked when cargo rebuilt nothing.
set -eu
in=$1
out=$2
if [ -f "$out" ] && [ "$out" -nt "$in" ] && [ "$out" -nt "$0" ]; then
    exit 0
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/localize_core.XXXXXX")
trap 'rm -rf "$work"' EXIT
# every entry the archive defines is a root of the section collection
# (readelf: nm hands the members to the system's LLVM plugin, which may be
# older than rustc's LLVM and then lists nothing)
readelf -sW "$in" |
    awk '($5 == "GLOBAL" || $5 == "WEAK") && $7 != "UND" && $8 ~ /^granbond_/ { print "--undefined=" $8 }' |
    sort -u >"$work/roots"
if [ ! -s "$work/roots" ]; then
    echo "localize_core.sh: no granbond_* symbol in $in" >&2
    exit 1
fi
# The input format is named so that neither tool hands the members to the
# system's LLVM plugin; the bitcode rustc keeps beside the machine code
# (.llvmbc, .llvmcmd) is not needed to link.
# shellcheck disable=SC2046
ld -r --gc-sections $(cat "$work/roots") -b elf64-x86-64 --whole-archive "$in" -o "$work/granbond.o"
objcopy -I elf64-x86-64 --wildcard --keep-global-symbol='granbond_*' --strip-debug \
    --remove-section=.llvmbc --remove-section=.llvmcmd "$work/granbond.o"
mkdir -p "$(dirname "$out")"
rm -f "$work/lib.a"
ar rcs "$work/lib.a" "$work/granbond.o"
mv "$work/lib.a" "$out"
