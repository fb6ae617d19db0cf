#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The main job: install what is missing, build, and run the paper's worked example
# (a = 10, b = 6, n = 4, from (10,0) to (0,6)) on the three engines (golden model,
# SystemC model, RTL under Verilator), show that their rows agree, and write both
# waveforms.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
# Only what the demo needs: the demo's packages, and the dda command (a build directory
# configured before keeps its settings, the test suite included).
"$root/scripts/setup.sh" --demo
if [ -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" >/dev/null
else
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DDDA_TESTS=OFF >/dev/null
fi
cmake --build "$build" --target dda -j "$(nproc)" >/dev/null
dda="$build/bin/dda"
args=(--a 10 --b 6 --bits 4 --preload zero)  # the paper's mode (half preload is the default)
out="$build/demo"
mkdir -p "$out"

echo "== dda trace ${args[*]} --format table"
"$dda" trace "${args[@]}" --format table
echo
echo "== dda stats ${args[*]}"
"$dda" stats "${args[@]}"
echo
echo "== dda path ${args[*]}"
"$dda" path "${args[@]}" | paste -sd' ' -
echo

echo "== the same trace on three engines"
"$dda" trace "${args[@]}" --engine golden --out "$out/trace-golden.csv"
"$dda" trace "${args[@]}" --engine systemc --vcd "$out/systemc.vcd" --out "$out/trace-systemc.csv"
"$dda" trace "${args[@]}" --engine rtl --vcd "$out/rtl.vcd" --out "$out/trace-rtl.csv"
status=0
for engine in systemc rtl; do
  if cmp -s "$out/trace-golden.csv" "$out/trace-$engine.csv"; then
    echo "engine $engine: $(($(wc -l < "$out/trace-$engine.csv") - 2)) iterations, rows identical to the golden engine's"
  else
    echo "engine $engine: rows DIFFER from the golden engine's:" >&2
    diff "$out/trace-golden.csv" "$out/trace-$engine.csv" >&2 || true
    status=1
  fi
done
if cmp -s "$out/trace-golden.csv" "$root/tests/data/table1-exact-trace.csv"; then
  echo "golden trace is byte-identical to the paper's exact trace (tests/data/table1-exact-trace.csv)"
else
  echo "golden trace differs from tests/data/table1-exact-trace.csv" >&2
  status=1
fi
echo
echo "== picture"
"$dda" plot "${args[@]}" --out "$out/plot.svg"
echo "path over the ideal ellipse: $out/plot.svg (the same picture: docs/paper_example_plot.png)"
echo
echo "== test vectors"
"$dda" vectors "${args[@]}" --out-dir "$out/vectors"
echo "vector set (golden model): $out/vectors (docs/vectors.md)"
"$root/scripts/vector-bench.sh" "$out/vectors" || status=1
echo
echo "== waveforms"
echo "SystemC model: $out/systemc.vcd   open: gtkwave $out/systemc.vcd $root/docs/dda_systemc.gtkw"
echo "RTL:           $out/rtl.vcd       open: gtkwave $out/rtl.vcd $root/docs/dda_rtl.gtkw"
exit $status
