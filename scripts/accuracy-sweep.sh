#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Accuracy sweep (issue 5): 2,000 arcs with a fixed seed through the golden model, the
# worst and mean distance of the path from the ideal ellipse per mode and aspect ratio.
# Prints the table and writes it into docs/results.md between its markers.
#   usage: scripts/accuracy-sweep.sh [arcs] [seed]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
"$root/scripts/build.sh" >/dev/null
arcs=${1:-2000} seed=${2:-2026}
table=$("$build/bin/accuracy_sweep" --arcs "$arcs" --seed "$seed")
echo "$table"
doc="$root/docs/results.md"
begin='<!-- BEGIN GENERATED: scripts/accuracy-sweep.sh -->'
end='<!-- END GENERATED: scripts/accuracy-sweep.sh -->'
tmp=$(mktemp)
awk -v b="$begin" -v e="$end" -v t="$table" -v cmd="scripts/accuracy-sweep.sh $arcs $seed" '
  $0 == b { print; print "Command: `" cmd "`, " strftime("%Y-%m-%d") "."; print ""; print t; skip = 1; next }
  $0 == e { skip = 0 }
  !skip { print }' "$doc" > "$tmp"
mv "$tmp" "$doc"
echo "wrote the table into docs/results.md"
