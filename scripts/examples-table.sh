#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The table of the part programs in examples/ (docs/results.md, "Part programs"): for
# each, `dda stats --program ... --format csv` on the golden model (the SystemC model and
# the RTL print the same: tests/check-examples.sh), summed over its blocks: commands,
# steps, iterations, the worst distance from the programmed geometry per kind of block,
# the largest rounding of an end point, and whether every block ended on its rounded end.
#   usage: scripts/examples-table.sh [--write]   (--write puts it into docs/results.md)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dda=${DDA_BUILD_DIR:-$root/build}/bin/dda
table="| program | machine | blocks | commands | steps | iterations | worst: lines (target 0.5) | arcs (0.8) | ellipses (0.8 / 1.0) | largest end rounding | every block on its rounded end | every block within its target (plus its ends' rounding) |
|---|---|---|---|---|---|---|---|---|---|---|---|"
for prog in "$root"/examples/*.ngc; do
  mapfile -t opts < <("$root/scripts/example-options.sh" "$prog")
  [ "${#opts[@]}" -ge 2 ] || { echo "examples-table: no options for $prog" >&2; exit 1; }
  machine=mill
  [[ " ${opts[*]} " == *" --machine lathe "* ]] && machine=lathe
  row=$("$dda" stats "${opts[@]}" --format csv | awk -F, -v name="$(basename "$prog")" -v machine="$machine" '
    NR == 1 { next }
    { blocks++; cmds += $9; steps += $10; iters += $11
      kind = $3 ~ /^(line|rapid)$/ ? "l" : $3 ~ /^arc/ ? "a" : "e"
      if (!(kind in worst) || $12 > worst[kind]) worst[kind] = $12
      if ($8 > rounding) rounding = $8
      if ($14 != "yes") off++
      if ($16 != "yes") over++ }
    function w(k) { return (k in worst) ? sprintf("%.3f", worst[k]) : "-" }
    END { printf "| `%s` | %s | %d | %d | %d | %d | %s | %s | %s | %.3f | %s | %s |\n", name, machine, blocks, cmds,
          steps, iters, w("l"), w("a"), w("e"), rounding, off ? "no" : "yes", over ? over " over" : "yes" }')
  table+=$'\n'"$row"
done
if [ "${1:-}" = "--write" ]; then
  echo "$table" | "$root/scripts/results-table.sh" scripts/examples-table.sh "scripts/examples-table.sh --write"
else
  echo "$table"
fi
