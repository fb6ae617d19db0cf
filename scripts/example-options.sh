#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The `dda` options an example program runs with, one per line: --program FILE and the
# --machine and --start of its "; Run:" comment line (examples/*.ngc). Used by
# tests/check-examples.sh and scripts/examples-table.sh.
#   usage: scripts/example-options.sh FILE
set -euo pipefail
prog=$1
run=$(grep -m1 '^; Run:' "$prog") || { echo "example-options: $prog has no '; Run:' line" >&2; exit 1; }
printf '%s\n' --program "$prog"
if [[ $run =~ --machine\ ([a-z]+) ]]; then printf '%s\n' --machine "${BASH_REMATCH[1]}"; fi
if [[ $run =~ --start\ ([-0-9.,]+) ]]; then printf '%s\n' --start "${BASH_REMATCH[1]}"; fi
