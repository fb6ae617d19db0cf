#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Accuracy sweep: 2,000 arcs with a fixed seed through the golden model, the
# worst and mean distance of the path from the ideal ellipse per mode and aspect ratio.
# Prints the table and writes it into docs/results.md between its markers.
#   usage: scripts/accuracy-sweep.sh [arcs] [seed]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
"$root/scripts/build.sh" >/dev/null
arcs=${1:-2000} seed=${2:-2026}
table=$("$build/bin/accuracy_sweep" --arcs "$arcs" --seed "$seed")
echo "$table"
echo "$table" | "$root/scripts/results-table.sh" scripts/accuracy-sweep.sh "scripts/accuracy-sweep.sh $arcs $seed"
