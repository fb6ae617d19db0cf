#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Install what is missing, build, and run the whole default test suite through ctest:
# every test but those labelled long (`scripts/regress.sh long` runs those). Longer
# regressions are scripts/regress.sh (see README, "Tests"). Arguments go to ctest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
"$root/scripts/build.sh"
cd "$build"
ctest --output-on-failure -j "$(nproc)" -LE '^long$' "$@"
