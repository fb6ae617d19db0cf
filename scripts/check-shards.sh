#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Shards add up: the totals of N shards of a regression, merged, equal one unsharded
# run's (every case draws from its own (seed, index) stream). Prints both and "equal".
#   usage: scripts/check-shards.sh [systemc|rtl|cosim] [cases] [shards] [seed]
#   (ctest regress.shards_add_up runs it with 80 cases on the RTL; docs/verification.md
#   quotes 2,000)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
engine=${1:-rtl} cases=${2:-2000} shards=${3:-4} seed=${4:-1}
case "$engine" in systemc) prog=sc_regress ;; rtl) prog=rtl_regress ;; cosim) prog=cosim_regress ;;
  *) echo "usage: $0 [systemc|rtl|cosim] [cases] [shards] [seed]" >&2; exit 2 ;; esac
prog=$build/bin/$prog
work=$(mktemp -d -t dda-shards.XXXXXX)
trap 'rm -rf "$work"' EXIT
"$prog" --arcs "$cases" --seed "$seed" > "$work/one.txt"
parallel --will-cite --halt now,fail=1 "$prog" --arcs "$cases" --seed "$seed" --shard {}/"$shards" --json "$work/s{}.json" \
  ::: $(seq 0 $((shards - 1))) > /dev/null
"$prog" --merge "$work"/s*.json > "$work/merged.txt"
cat "$work/one.txt" "$work/merged.txt"
# The same totals and coverage, but for the run's name ("N shards merged").
if diff <(sed 's/^[a-z]* regression: [^:]*: //' "$work/one.txt") <(sed 's/^[a-z]* regression: [^:]*: //' "$work/merged.txt"); then
  echo "check-shards: $shards shards of $cases cases merged equal the unsharded run"
else
  echo "check-shards: the merged totals DIFFER from the unsharded run" >&2
  exit 1
fi
