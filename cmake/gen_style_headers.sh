#!/bin/sh
# Generate the style_<kind>_model.h headers that Debian's libliggghts-dev omits.
# Same idea as LIGGGHTS's "Make.sh style": for every installed header
# <kind>_model_*.h that contains a "<KIND>_MODEL(" registration line, emit an
# #include of it. Optional extra headers (our own models) can be appended,
# but for the adapter we deliberately do NOT append them: the generated files
# must describe exactly what the stock library was compiled with.
# usage: gen_style_headers.sh <liggghts include dir> <output dir>
set -eu
inc=${1:-/usr/include/liggghts}
out=${2:-gen}
mkdir -p "$out"
for kind in surface normal tangential cohesion rolling; do
  KIND=$(echo "$kind" | tr a-z A-Z)
  tmp="$out/style_${kind}_model.h.tmp"
  : > "$tmp"
  for f in $(cd "$inc" && ls ${kind}_model_*.h 2>/dev/null | sort); do
    if grep -q "^[[:space:]]*${KIND}_MODEL(" "$inc/$f"; then
      echo "#include \"$f\"" >> "$tmp"
    fi
  done
  # only touch the file if it changed (keeps builds incremental)
  if [ -f "$out/style_${kind}_model.h" ] && cmp -s "$tmp" "$out/style_${kind}_model.h"; then
    rm -f "$tmp"
  else
    mv "$tmp" "$out/style_${kind}_model.h"
  fi
done
# style_contact_model.h is only read by granular_styles.h (stock whitelist); we
# never include granular_styles.h, but provide an empty one for safety.
[ -f "$out/style_contact_model.h" ] || : > "$out/style_contact_model.h"
