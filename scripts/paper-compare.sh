#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The lathe paper's macro program against one native ellipse block (docs/results.md,
# "The lathe paper's macro program"): tb/measure/paper_compare on
# examples/lathe-paper-macro.ngc and examples/lathe-paper-native.ngc (golden model; the
# SystemC model and the RTL run both identically: tests/check-examples.sh). Prints the
# table; with --write also puts it into docs/results.md and draws both paths
# (docs/paper_macro_vs_native.svg) and a close-up (docs/paper_macro_vs_native_closeup.svg);
# at feeds, the programs' planned and paced times and both speed profiles at 2000 mm/min
# (docs/paper_speed-macro.svg, docs/paper_speed-native.svg; about 30 s).
#   usage: scripts/paper-compare.sh [--write]   (after the build; DDA_BUILD_DIR as elsewhere)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${DDA_BUILD_DIR:-$root/build}/bin
# The feeds of the second table (mm/min), at 500 mm/s^2 on every axis and a junction
# deviation of 0.01 mm (the lathe's other limits: docs/programs.md, "Feeds and speeds").
args=(--macro "$root/examples/lathe-paper-macro.ngc" --native "$root/examples/lathe-paper-native.ngc"
  --feeds 100,1000,2000,4000 --accel 500 --junction-deviation 0.01)
if [ "${1:-}" = "--write" ]; then
  table=$("$bin/paper_compare" "${args[@]}" --svg "$root/docs/paper_macro_vs_native.svg" \
    --closeup "$root/docs/paper_macro_vs_native_closeup.svg" --speed-svg "$root/docs/paper_speed" --speed-feed 2000)
  echo "$table" | "$root/scripts/results-table.sh" scripts/paper-compare.sh "scripts/paper-compare.sh --write"
  echo "$table"
else
  "$bin/paper_compare" "${args[@]}"
fi
