#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The lathe paper's macro program against one native ellipse block (docs/results.md,
# "The lathe paper's macro program"): tb/measure/paper_compare on
# examples/lathe-paper-macro.ngc and examples/lathe-paper-native.ngc (golden model; the
# SystemC model and the RTL run both identically: tests/check-examples.sh). Prints the
# table; with --write also puts it into docs/results.md and draws both paths
# (docs/paper_macro_vs_native.svg) and a close-up (docs/paper_macro_vs_native_closeup.svg).
#   usage: scripts/paper-compare.sh [--write]   (after the build; DDA_BUILD_DIR as elsewhere)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${DDA_BUILD_DIR:-$root/build}/bin
args=(--macro "$root/examples/lathe-paper-macro.ngc" --native "$root/examples/lathe-paper-native.ngc")
if [ "${1:-}" = "--write" ]; then
  table=$("$bin/paper_compare" "${args[@]}" --svg "$root/docs/paper_macro_vs_native.svg" \
    --closeup "$root/docs/paper_macro_vs_native_closeup.svg")
  echo "$table" | "$root/scripts/results-table.sh" scripts/paper-compare.sh "scripts/paper-compare.sh --write"
  echo "$table"
else
  "$bin/paper_compare" "${args[@]}"
fi
