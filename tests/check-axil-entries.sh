#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The block-entry words of `dda entries` and of the Python module drive the motion block
# behind its AXI4-Lite bridge in a bench written from the docs alone
# (tb/hdl/dda_axil_entries_tb.v, Icarus): the paper's arc, a line of three axes, an arc
# turned by 30 degrees, and a short program at its planned speeds (ACCEL and VMIN as
# `dda entries` gives them); each ends with the position registers and the pins' steps
# on the last piece's end. A corrupted word (the first entry's X count one higher) fails.
#   usage: tests/check-axil-entries.sh DDA PYTHONPATH
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 DDA PYTHONPATH" >&2; exit 2; }
dda=$1 pypath=$2
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mapfile -t srcs < <("$root/scripts/rtl-files.sh" "$root/rtl/dda_motion_axil.f")
iverilog -g2012 -I "$root/rtl" -o "$tmp/tb.vvp" "${srcs[@]}" "$root/tb/hdl/dda_axil_entries_tb.v"

# JSON of entries (dda entries --format json, or the module's dict) -> the bench's file.
tohex() {  # IN OUT [corrupt]
  python3 - "$@" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
words = [len(d["pieces"]), d["accel"] or 0, d["vmin"] or 0]
for p in d["pieces"]:
    words += p["words"] + list(p["from"]) + list(p["to"])
if len(sys.argv) > 3:  # the first entry's X count one higher (DDA_MOTION_CMD_CNT_X_AT 255: word 7, bit 31)
    words[3 + 7] ^= 1 << 31
with open(sys.argv[2], "w") as f:
    f.write("\n".join("%08x" % (w & 0xFFFFFFFF) for w in words) + "\n")
PY
}
bench() {  # NAME HEXFILE
  if ! vvp -n "$tmp/tb.vvp" +entries="$2" >"$tmp/$1.log" 2>&1 || ! grep -q '^PASS' "$tmp/$1.log"; then
    cat "$tmp/$1.log" >&2
    return 1
  fi
  echo "check-axil-entries: $1: $(grep -E '^(end|PASS)' "$tmp/$1.log" | tr '\n' ' ')"
}

cat >"$tmp/prog.ngc" <<'NGC'
G21 G90 G17
G1 F1200 X1 Y0.5
X0 Y1
G2 X0 Y0 I0 J-0.5
M2
NGC
n=0
for args in "--a 10 --b 6 --bits 4 --preload zero" "--line --from 3,-2,1 --to -40,17,9" \
            "--a 60 --b 25 --angle 30 --from-theta 10 --to-theta 200" \
            "--program $tmp/prog.ngc --machine-config $root/examples/machine-sim.json --clock 200000"; do
  n=$((n + 1))
  # shellcheck disable=SC2086
  "$dda" entries $args --format json >"$tmp/e$n.json"
  tohex "$tmp/e$n.json" "$tmp/e$n.hex"
  bench "dda-$n" "$tmp/e$n.hex"
done
# The same program's words from Python.
PYTHONPATH=$pypath python3 - "$tmp/prog.ngc" "$root/examples/machine-sim.json" "$tmp/py.json" <<'PY'
import json, sys
import dda
d = dda.program_entry_words(program=sys.argv[1], machine_config=sys.argv[2], clock=200000)
json.dump(d, open(sys.argv[3], "w"))
PY
tohex "$tmp/py.json" "$tmp/py.hex"
cmp -s "$tmp/py.hex" "$tmp/e$n.hex" || { echo "check-axil-entries: Python's words differ from dda's" >&2; exit 1; }
bench python "$tmp/py.hex"
# A corrupted word must fail.
tohex "$tmp/e1.json" "$tmp/bad.hex" corrupt
if bench corrupted "$tmp/bad.hex" 2>/dev/null; then echo "check-axil-entries: a corrupted entry passed" >&2; exit 1; fi
echo "check-axil-entries: pass ($n sets from dda, one from Python; a corrupted one fails)"
