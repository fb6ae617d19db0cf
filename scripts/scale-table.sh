#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Programs of CAM size through the stream (docs/results.md, "Programs of CAM size"): for
# 10^3 .. 10^6 blocks (a generated program of one-millimetre lines and half circles of
# one millimetre, one quarter ellipse per 100 blocks, on a 0.001 mm lattice) the time
# and the peak resident memory (GNU time) of `dda stats --program` and `dda path
# --program` on the golden model, and stats' iterations per second beside the golden
# datapath's bare rate (golden_bench: Datapath::step with records off, measured in the
# same run, next to each row), and the speed planner's run (`dda stats --program --speeds`
# at a default feed of 1000 mm/min: reader, block planner, lookahead; no datapath but
# the curved pieces it cuts) with its time per block. Then one arc at the largest semi-axis `dda stats` takes
# (2^30 steps). A benchmark: it prints figures and asserts nothing.
#   usage: scripts/scale-table.sh [--write] [--max-exp N]   (--write: into docs/results.md)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
dda=$build/bin/dda
write=0 max_exp=6
while [ $# -gt 0 ]; do
  case "$1" in
    --write) write=1; shift ;;
    --max-exp) max_exp=$2; shift 2 ;;
    *) echo "usage: $0 [--write] [--max-exp N]" >&2; exit 2 ;;
  esac
done
[ -x /usr/bin/time ] || { echo "scale-table: GNU time (/usr/bin/time) is missing: scripts/setup.sh installs it" >&2; exit 1; }
work=$(mktemp -d -t dda-scale.XXXXXX)
trap 'rm -rf "$work"' EXIT

# gen N: a program of N motion blocks. X runs back and forth between 0 and 100 mm:
# blocks advance 1 mm (a line, or every third block a half circle below the chord),
# every 100th is a quarter ellipse (A 2, B 1) up 1 mm and on 2 mm; at the ends of a row
# a line of 1 mm in Y turns back.
gen() {
  awk -v n="$1" 'BEGIN {
    print "%1"; print "G21 G90 G17"; print "G00 X0 Y0"
    x = 0; y = 0; d = 1
    for (k = 1; k < n; k++) {
      if ((d > 0 && x + 2 > 100) || (d < 0 && x - 2 < 0)) { y += 1; d = -d; printf "G01 Y%d\n", y; continue }
      if (k % 100 == 0) {
        x += 2 * d; y += 1
        printf "%s X%d Y%d A2 B1 Q0 I0 J1\n", (d > 0 ? "G6.3" : "G6.2"), x, y
      } else if (k % 3 == 0) {
        printf "%s X%d Y%d I%.1f J0\n", (d > 0 ? "G03" : "G02"), x + d, y, 0.5 * d; x += d
      } else {
        x += d; printf "G01 X%d\n", x
      }
    }
    print "M30" }'
}

# measure LABEL CMD...: "seconds kilobytes" of one run (its output to /dev/null)
measure() {
  /usr/bin/time -f '%e %M' -o "$work/time" "$@" > "$work/out" 2> "$work/err" ||
    { echo "scale-table: failed: $* ($(cat "$work/err"))" >&2; exit 1; }
  cat "$work/time"
}

# The bare rate: the median of 5 runs of 3.3e7 iterations each. Measured right before and
# right after each row's `stats` (the machine's speed drifts on a shared host), and the
# larger of the two taken, so the row's ratio is not flattered by a slow moment.
bare_rate() {
  "$build/bin/golden_bench" --reps 5 --radius 200000 | awk '{print $3 / $6}' | sort -g | awk 'NR == 3'
}
bares=""
table="| blocks | program size | iterations | \`stats\`: time | peak memory | iterations/s | of the bare rate | \`path\`: time | peak memory | \`stats --speeds\`: time | peak memory | per block |
|---|---|---|---|---|---|---|---|---|---|---|---|"
for e in $(seq 3 "$max_exp"); do
  n=$((10 ** e))
  gen "$n" > "$work/p.ngc"
  size=$(du -h "$work/p.ngc" | cut -f1)
  b1=$(bare_rate)
  read -r st_s st_kb < <(measure "$dda" stats --program "$work/p.ngc")
  b2=$(bare_rate)
  bare=$(awk -v a="$b1" -v b="$b2" 'BEGIN {print (a > b ? a : b)}')
  bares+=" $b1 $b2"
  iters=$(awk '$1 == "iterations:" {print $2}' "$work/out")
  blocks=$(awk '$1 == "blocks:" {print $2}' "$work/out")
  read -r pa_s pa_kb < <(measure "$dda" path --program "$work/p.ngc")
  read -r sp_s sp_kb < <(measure "$dda" stats --program "$work/p.ngc" --speeds --default-feed 1000)
  rate=$(awk -v i="$iters" -v s="$st_s" 'BEGIN {printf "%.0f", (s > 0 ? i / s : 0)}')
  table+=$'\n'"$(awk -v b="$blocks" -v sz="$size" -v i="$iters" -v ss="$st_s" -v sk="$st_kb" -v r="$rate" \
    -v bare="$bare" -v ps="$pa_s" -v pk="$pa_kb" -v qs="$sp_s" -v qk="$sp_kb" 'BEGIN {
      printf "| %d | %s | %.0f | %.2f s | %.1f MB | %.3g | %.2f | %.2f s | %.1f MB | %.2f s | %.1f MB | %.1f us |", b, sz, i,
        ss, sk / 1024, r, r / bare, ps, pk / 1024, qs, qk / 1024, 1e6 * qs / b }')"
done
read -r arc_s arc_kb < <(measure "$dda" stats --a 1073741824 --b 1)
arc_iters=$(awk '$1 == "iterations:" {print $2}' "$work/out")
table+=$'\n\n'"$(printf 'One arc at the largest semi-axis, `dda stats --a 1073741824 --b 1`: %s iterations, %.2f s, %.1f MB peak.' \
  "$arc_iters" "$arc_s" "$(awk -v k="$arc_kb" 'BEGIN {print k / 1024}')")"
read -r bmin bmax < <(echo "$bares" | tr ' ' '\n' | awk 'NF {if (n == 0 || $1 < lo) lo = $1; if ($1 > hi) hi = $1; n++}
  END {printf "%.3g %.3g\n", lo, hi}')
table+=$'\n'"$(printf 'The golden datapath'"'"'s bare rate in the same run (golden_bench, median of 5 runs of 3.3e7 iterations, before and after each row'"'"'s `stats`; a row divides by the larger of its two): %s to %s iterations/s.' "$bmin" "$bmax")"
if [ "$write" = 1 ]; then
  echo "$table" | "$root/scripts/results-table.sh" scripts/scale-table.sh "scripts/scale-table.sh --write"
else
  echo "$table"
fi
