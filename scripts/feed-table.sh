#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The feed table of docs/results.md ("What the DDA does to the feed"): `dda feed --summary`
# on the paper's example, the lathe example and a circle. At a constant feed increment
# the core iterates at a constant rate; its speed along the path per iteration is
# |(jv_x, jv_y)| / cap (the integrands are the velocity), which an ellipse varies.
#   usage: scripts/feed-table.sh   (after the build; DDA_BUILD_DIR as in the other scripts)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dda=${DDA_BUILD_DIR:-$root/build}/bin/dda
echo "| arc | pieces | iterations | path (steps) | speed per iteration: min / mean / max (steps) | ripple within a piece (max/min, worst piece) | feed error, each piece at its own increment | feed error, one increment for the arc |"
echo "|---|---|---|---|---|---|---|---|"
"$dda" feed --summary --label "the paper's example (\`--a 10 --b 6 --bits 4 --preload zero\`)" --a 10 --b 6 --bits 4 --preload zero
"$dda" feed --summary --label "the paper's example, half preload, default capacity" --a 10 --b 6 --preload half
"$dda" feed --summary --label "the lathe example (a 25000, b 15000, 330 degrees, 60 to 136 degrees)" \
  --a 25000 --b 15000 --angle 330 --center -30000,5000 --from-theta 60 --to-theta 136 --dir ccw --preload zero
"$dda" feed --summary --label "a quarter ellipse a 2000, b 500" --a 2000 --b 500 --preload half
"$dda" feed --summary --label "a full circle of radius 2000" --a 2000 --b 2000 --from-theta 0 --to-theta 0 --preload half
