#!/bin/bash
# check-links.sh RANK:LIBRARY...: every library's undefined symbols are defined by the library
# itself or by a library of a lower rank (README: "The code's map"): the links point down, as the
# includes do (tests/test_layers.cpp). Libraries of one rank are siblings: neither may use the
# other. A symbol no library of the project defines (the C++ library's, Eigen's) is not checked.
# Prints each breach, "LIBRARY uses SYMBOL, defined only in OTHER (above or beside it)", and fails.
set -euo pipefail
export LC_ALL=C
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
symbols() {  # the defined (D) or undefined (U) external symbols of a library, one a line
  local kind=$1 library=$2 dynamic=
  case $library in *.so) dynamic=-D ;; esac
  if [ "$kind" = D ]; then nm $dynamic -g --defined-only "$library" 2>/dev/null
  else nm $dynamic -g --undefined-only "$library" 2>/dev/null; fi |
    awk 'NF >= 2 { print $NF }' | sort -u
}
for entry in "$@"; do
  rank=${entry%%:*} library=${entry#*:}
  name=$(basename "$library")
  [ -f "$library" ] || { echo "check-links: $library: no such library"; exit 2; }
  symbols D "$library" | sed "s|\$| $rank $name|" >> "$work/defined"
  symbols U "$library" > "$work/undefined.$name"
  echo "$rank $name" >> "$work/libraries"
done
sort -k1,1 "$work/defined" > "$work/defined.sorted"
breaches=0
while read -r rank name; do
  # For each undefined symbol: the lowest rank that defines it and whether this library does.
  result=$(join -j1 "$work/undefined.$name" "$work/defined.sorted" |
    awk -v own="$rank" -v me="$name" '
      { if (!($1 in low) || $2 < low[$1]) low[$1] = $2
        if ($3 == me || $2 < own) ok[$1] = 1
        where[$1] = where[$1] (where[$1] == "" ? "" : ", ") $3 }
      END { for (s in low) if (!(s in ok)) print s "\t" where[s] }')
  if [ -n "$result" ]; then
    while IFS=$'\t' read -r symbol where; do
      echo "$name uses $(echo "$symbol" | c++filt), defined only in $where (above or beside it)"
      breaches=$((breaches + 1))
    done <<< "$result"
  fi
done < "$work/libraries"
count=$(wc -l < "$work/libraries")
if [ "$breaches" -gt 0 ]; then
  echo "check-links: $breaches symbols used against the layers' order"
  exit 1
fi
echo "check-links: $count libraries, every link points down"
