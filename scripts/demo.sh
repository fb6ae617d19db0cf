#!/usr/bin/env bash
# The main job: install what is missing, build, and run the paper's worked example
# (a = 10, b = 6, n = 4, from (10,0) to (0,6)), checking the trace against the spec.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
"$root/scripts/build.sh" >/dev/null
dda="$build/tb/dda"
args=(--a 10 --b 6 --bits 4)

echo "== dda trace ${args[*]} --format table"
"$dda" trace "${args[@]}" --format table
echo
echo "== dda stats ${args[*]}"
"$dda" stats "${args[@]}"
echo
echo "== dda path ${args[*]}"
"$dda" path "${args[@]}" | paste -sd' ' -
echo
out="$build/demo"
mkdir -p "$out"
"$dda" trace "${args[@]}" --format csv --out "$out/trace-golden.csv"
if cmp -s "$out/trace-golden.csv" "$root/tests/data/table1-exact-trace.csv"; then
  echo "trace CSV ($out/trace-golden.csv) is byte-identical to the paper's exact trace"
else
  echo "trace CSV differs from tests/data/table1-exact-trace.csv" >&2
  exit 1
fi
