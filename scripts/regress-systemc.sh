#!/usr/bin/env bash
# Long regression of the SystemC model against the golden model (not in the default
# suite): 2,000 random arcs by default. usage: scripts/regress-systemc.sh [arcs] [seed]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
"$root/scripts/build.sh" >/dev/null
"$build/tb/sc_regress" --arcs "${1:-2000}" --seed "${2:-1}"
