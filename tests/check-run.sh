#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `dda run` on the sim port (docs/programs.md, "Running a program live"), as a user runs
# it, checked from what it prints and its exit status:
#   examples  programs of examples/ run to their end (exit 0): the block's position
#             registers on the program's end, the steps counted at the pins equal to
#             them, the pins' peak path acceleration within 5% of the planned one, and
#             status lines printed; one program also from standard input;
#   all       the same on every example (long);
#   stops     each stop's exit status and message: E-stop, a limit (at once and
#             ramped), the host dying (the watchdog), the operator's soft and hard stop
#             from a control file, a hold, a resume and override changes that still end
#             the program, program stops (M00, M01) that wait for a resume, a bad port,
#             a bad control file;
#   signals   SIGUSR1/SIGUSR2 hold and resume, SIGINT a soft stop;
#   pty       the keys on a (pseudo-)terminal: hold, resume, override up, soft stop.
#   usage: tests/check-run.sh examples|all|stops|signals|pty DDA EXAMPLES_DIR
set -euo pipefail
[ $# -eq 3 ] || { echo "usage: $0 examples|all|stops|signals|pty DDA EXAMPLES_DIR" >&2; exit 2; }
mode=$1 dda=$2 dir=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cfg=$dir/machine-sim.json
fail() { echo "check-run: $*" >&2; exit 1; }
# The path acceleration the planner gives the sim machine: half the smallest axis'
# (500 mm/s^2 by default), at 100 steps per mm.
accel_steps=25000

# run NAME EXPECTED_STATUS ARGS...: runs dda run, its stdout in $tmp/NAME.out, stderr
# in $tmp/NAME.err; fails unless the status is the expected one.
run() {
  local name=$1 want=$2
  shift 2
  local got=0
  "$dda" run "$@" >"$tmp/$name.out" 2>"$tmp/$name.err" || got=$?
  [ "$got" = "$want" ] || { cat "$tmp/$name.err" >&2; fail "$name: exit status $got, expected $want"; }
}
# Fails unless the file holds the (extended) regular expression.
has() { grep -Eq -- "$2" "$tmp/$1" || { cat "$tmp/$1" >&2; fail "$1 does not say /$2/"; }; }
# The pins' count equals the registers and their peak acceleration is the plan's.
pins_ok() {
  has "$1.out" '\(equal to the position registers\)'
  local peak
  peak=$(sed -n 's/.*peak path acceleration \([0-9]*\) steps.*/\1/p' "$tmp/$1.out")
  [ -n "$peak" ] || fail "$1: no peak acceleration"
  [ "$peak" -le $((accel_steps * 105 / 100)) ] || fail "$1: the pins' peak acceleration $peak steps/s^2 is over $accel_steps"
}
example() {
  local prog=$1 name
  name=$(basename "$prog" .ngc)
  mapfile -t opts < <("$(dirname "$0")/../scripts/example-options.sh" "$prog")
  # (the example's --machine and --start, without --program; a lathe's machine)
  local c=$cfg
  [[ " ${opts[*]} " == *" --machine lathe "* ]] && c=$dir/lathe-sim.json
  run "$name" 0 "$prog" "${opts[@]:2}" --machine-config "$c" --status-every 2
  pins_ok "$name"
  has "$name.out" '^line [0-9]+ \(block [0-9]+\) \| X '
  has "$name.out" '100% left 0.0 s'
  echo "check-run: $name: $(grep '^time:' "$tmp/$name.out")"
}

case $mode in
  examples)
    for p in feeds lines lines-3d planes helix mill-contour lathe-profile; do example "$dir/$p.ngc"; done
    run stdin 0 - --machine-config "$cfg" --status-every 2 <"$dir/lines.ngc"
    pins_ok stdin
    ;;
  all)
    for p in "$dir"/*.ngc; do example "$p"; done
    ;;
  stops)
    run estop 3 "$dir/lines.ngc" --machine-config "$cfg" --port sim:estop=1.5 --quiet
    has estop.err '^dda: stop: E-stop at line 8 \(block 2\)'
    has estop.out '\(equal to the position registers\)'
    python3 - "$cfg" "$tmp/limit.json" "$tmp/decel.json" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
c["axes"]["x"]["limit_pos_mm"] = 20
json.dump(c, open(sys.argv[2], "w"))
c["inputs"]["limit_decel"] = True
json.dump(c, open(sys.argv[3], "w"))
PY
    run limit 4 "$dir/lines.ngc" --machine-config "$tmp/limit.json" --quiet
    has limit.err '^dda: stop: limit switch: X limit, positive end at line 8 \(block 2\), latched at X 20.000 Y 5.000'
    has limit.out '^position: X 20.000 Y 5.000'
    run decel 4 "$dir/lines.ngc" --machine-config "$tmp/decel.json" --quiet
    has decel.err 'latched at X 20.000 Y 5.000'
    pins_ok decel  # (a ramp to rest at ACCEL past the switch)
    run dies 5 "$dir/lines.ngc" --machine-config "$cfg" --port sim:host-dies=1.5 --quiet
    has dies.err "^dda: stop: the host stopped writing at 1.500 s: the block's watchdog ran out and it came to rest"
    pins_ok dies
    printf '@1 hold\n@2.5 resume\n@3 override 150\n@4 stop\n' >"$tmp/ops"
    run soft 7 "$dir/lines.ngc" --machine-config "$cfg" --control "$tmp/ops" --quiet
    has soft.err '^dda: stop: soft stop by the operator at line 9'
    has soft.out '^dda run: feed hold at 1.00'
    has soft.out '^dda run: override 150% at 3.00'
    pins_ok soft
    printf '@1 hard-stop\n' >"$tmp/hard"
    run hard 7 "$dir/lines.ngc" --machine-config "$cfg" --control "$tmp/hard" --quiet
    has hard.err '^dda: stop: hard stop by the operator'
    has hard.out '\(equal to the position registers\)'
    # A hold, its end and override changes: the program still ends, later.
    printf '@1 hold\n@2 resume\n@3 override 50\n@4 override +\n@5 override 200\n' >"$tmp/ops2"
    run held 0 "$dir/lines.ngc" --machine-config "$cfg" --control "$tmp/ops2" --status-every 0.5
    pins_ok held
    has held.out '\| held \|'
    has held.out '^dda run: override 60% at 4.00'
    # A program stop waits at rest for the operator's resume.
    printf 'G21 G90 G17\nG1 F600 X5\nM0\nX10\nM1\nX12\nM2\n' >"$tmp/stops.ngc"
    printf '@2 resume\n@4 resume\n' >"$tmp/ops3"
    run mstop 0 "$tmp/stops.ngc" --machine-config "$cfg" --control "$tmp/ops3" --quiet
    has mstop.out '^dda run: program stop \(M00/M01\) before line 4 at 0\.[0-9]+ s: waiting for a resume'
    has mstop.out '^dda run: resume at 2\.00'
    has mstop.out '^dda run: program stop \(M00/M01\) before line 6'
    has mstop.out '^time: 4\.[0-9]+ s'
    pins_ok mstop
    run badport 2 "$dir/lines.ngc" --machine-config "$cfg" --port usb0
    has badport.err "port = 'usb0' is invalid"
    echo "dance" >"$tmp/badctl"
    run badctl 2 "$dir/lines.ngc" --machine-config "$cfg" --control "$tmp/badctl" --quiet
    has badctl.err "badctl:1: 'dance' is not a request"
    ;;
  pty)
    # The operator's keys on a terminal (a pseudo-terminal here): a hold, its end, the
    # override up, a soft stop; the pins' ramps within the planned acceleration.
    got=0
    python3 - "$dda" "$dir/mill-contour.ngc" "$cfg" "$tmp/pty.out" "$tmp/pty.err" <<'PY' || got=$?
import os, pty, subprocess, sys, time
dda, prog, cfg, out, err = sys.argv[1:]
master, slave = pty.openpty()
with open(out, "w") as o, open(err, "w") as e:
    p = subprocess.Popen([dda, "run", prog, "--machine-config", cfg, "--status-every", "1"], stdin=slave, stdout=o,
                         stderr=e)
    os.close(slave)
    t0 = time.monotonic()
    for at, key in ((1.0, b"!"), (2.0, b"~"), (2.5, b"+"), (3.5, b"s")):
        time.sleep(max(0.0, t0 + at - time.monotonic()))
        os.write(master, key)
    sys.exit(p.wait())
PY
    [ "$got" = 7 ] || { cat "$tmp/pty.err" >&2; fail "pty: exit status $got, expected 7"; }
    has pty.out '^dda run: feed hold at'
    has pty.out '^dda run: resume at'
    has pty.out '^dda run: override 110% at'
    has pty.err '^dda: stop: soft stop by the operator'
    pins_ok pty
    ;;
  signals)
    # Each long enough that the signals arrive while it runs.
    "$dda" run "$dir/mill-contour.ngc" --machine-config "$cfg" --status-every 1 >"$tmp/sig.out" 2>"$tmp/sig.err" &
    pid=$!
    sleep 2
    kill -USR1 $pid
    sleep 1
    kill -USR2 $pid
    sleep 1
    kill -INT $pid
    got=0
    wait $pid || got=$?
    [ "$got" = 7 ] || { cat "$tmp/sig.err" >&2; fail "signals: exit status $got, expected 7"; }
    has sig.out '^dda run: feed hold at'
    has sig.out '^dda run: resume at'
    has sig.err '^dda: stop: soft stop by the operator'
    pins_ok sig
    ;;
  *) echo "usage: $0 examples|all|stops|signals|pty DDA EXAMPLES_DIR" >&2; exit 2 ;;
esac
echo "check-run: $mode: pass"
