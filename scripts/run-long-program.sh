#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `dda run --port sim` on a generated program of many short blocks (about ten steps
# each on examples/machine-sim.json's 100 steps per mm), against a one-block program on
# the same port: both must run to their end (exit 0, the pins' count equal to the
# position registers), and the long run's peak memory (`/usr/bin/time`'s maximum
# resident set) must stay within 64 MB of the short one's: the run is a stream, its
# memory the planners' windows, not the program's length. Not in the default suite: at
# the default 100,000 blocks it simulates about half an hour of the machine's time.
#   usage: scripts/run-long-program.sh [BLOCKS] [BUILD_DIR]
set -euo pipefail
blocks=${1:-100000}
build=${2:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
dda=$build/bin/dda
[ -x "$dda" ] || { echo "run-long-program: no $dda (build first)" >&2; exit 2; }
[ -x /usr/bin/time ] || { echo "run-long-program: /usr/bin/time is missing (apt-get install time)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# A zigzag of 0.1 mm moves, X then Y, at 300 mm/min (the sim port's link keeps up).
python3 - "$blocks" "$tmp/long.ngc" "$tmp/one.ngc" <<'PY'
import sys
n = int(sys.argv[1])
with open(sys.argv[2], "w") as f:
    f.write("G21 G90 G17\nG1 F300\n")
    x = y = 0
    for k in range(n):
        if k % 2 == 0:
            x += 1 if (k // 2) % 200 < 100 else -1
        else:
            y += 1
        f.write(f"X{x / 10:.1f} Y{y / 10:.1f}\n")
    f.write("M2\n")
with open(sys.argv[3], "w") as f:
    f.write("G21 G90 G17\nG1 F300 X0.1\nM2\n")
PY
cfg=$root/examples/machine-sim.json
measure() {  # NAME PROGRAM: runs it, prints its peak memory in kB
  /usr/bin/time -f '%M' -o "$tmp/$1.mem" "$dda" run "$2" --machine-config "$cfg" --status-every 60 >"$tmp/$1.out" 2>"$tmp/$1.err" ||
    { cat "$tmp/$1.err" >&2; echo "run-long-program: $1 failed" >&2; exit 1; }
  grep -q '(equal to the position registers)' "$tmp/$1.out" || { cat "$tmp/$1.out" >&2; exit 1; }
  tail -1 "$tmp/$1.mem"
}
one=$(measure one "$tmp/one.ngc")
echo "run-long-program: one block: peak memory $one kB"
long=$(measure long "$tmp/long.ngc")
grep '^time:' "$tmp/long.out" | sed 's/^/run-long-program: /'
echo "run-long-program: $blocks blocks: peak memory $long kB ($(( (long - one) / 1024 )) MB over one block)"
[ $((long - one)) -le $((64 * 1024)) ] || { echo "run-long-program: more than 64 MB over one block" >&2; exit 1; }
echo "run-long-program: pass"
