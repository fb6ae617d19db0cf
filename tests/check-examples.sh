#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The part programs of examples/ on the three engines: for each program, `dda trace`
# prints the same bytes with --engine golden, systemc and rtl (the SystemC and RTL
# engines also check every iteration's registers against the golden model as they run);
# a program over TRACE_MAX_ITERATIONS iterations compares `dda path` instead. With
# --all, `dda stats` and `dda path` are compared too (every report of every program: the
# three reports are sinks of the same records, so the trace alone already decides the
# others; --all checks that the sinks agree as well, three times the time). The machine
# and start of each program come from its "; Run:" comment line. The accuracy and
# end-point checks of the same programs are in tests/test_program_plan.cpp.
#   usage: tests/check-examples.sh [--all] DDA EXAMPLES_DIR
set -euo pipefail
all=0
[ "${1:-}" = --all ] && { all=1; shift; }
[ $# -eq 2 ] || { echo "usage: $0 [--all] DDA EXAMPLES_DIR" >&2; exit 2; }
dda=$1 dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
TRACE_MAX_ITERATIONS=1200000
n=0
for prog in "$dir"/*.ngc; do
  name=$(basename "$prog" .ngc)
  mapfile -t opts < <("$(dirname "$0")/../scripts/example-options.sh" "$prog")
  [ "${#opts[@]}" -ge 2 ] || { echo "examples: no options for $prog" >&2; exit 1; }
  iters=$("$dda" stats "${opts[@]}" --format json | sed -n 's/^  "iterations": \([0-9]*\),$/\1/p' | tail -1)
  [ -n "$iters" ] || { echo "examples: no iteration count for $name" >&2; exit 1; }
  if [ "$all" = 1 ]; then
    cmds=(stats path)
    [ "$iters" -le "$TRACE_MAX_ITERATIONS" ] && cmds+=(trace)
  elif [ "$iters" -le "$TRACE_MAX_ITERATIONS" ]; then
    cmds=(trace)
  else
    cmds=(path)
  fi
  for cmd in "${cmds[@]}"; do
    for engine in golden systemc rtl; do
      "$dda" "$cmd" "${opts[@]}" --engine "$engine" --out "$tmp/$name.$cmd.$engine"
    done
    for engine in systemc rtl; do
      if ! cmp -s "$tmp/$name.$cmd.golden" "$tmp/$name.$cmd.$engine"; then
        echo "examples: dda $cmd ${opts[*]} differs between golden and $engine:" >&2
        diff "$tmp/$name.$cmd.golden" "$tmp/$name.$cmd.$engine" | head -5 >&2
        exit 1
      fi
    done
  done
  echo "examples: $name: ${cmds[*]} identical on golden, systemc and rtl ($iters iterations)"
  n=$((n + 1))
done
[ "$n" -ge 7 ] || { echo "examples: only $n programs in $dir (expected at least 7)" >&2; exit 1; }
echo "examples: $n programs identical on the three engines"
