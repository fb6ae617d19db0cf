#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Install what is missing, configure and build into build/ (or $DDA_BUILD_DIR).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
"$root/scripts/setup.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DDDA_TESTS=ON >/dev/null
cmake --build "$build" -j "$(nproc)"
