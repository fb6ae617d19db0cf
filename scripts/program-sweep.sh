#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Accuracy sweep of arcs as part programs give them (tb/measure/program_sweep.cpp):
# 20,000 fixed-seed cases by default, cut into shards run with GNU parallel (one per core;
# PARALLEL_OPTS may add --sshlogin to spread them over hosts with the same build), the
# shards' JSON merged into one table, which is printed and written into docs/results.md.
#   usage: scripts/program-sweep.sh [cases] [seed] [shards]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
"$root/scripts/build.sh" >/dev/null
cases=${1:-20000} seed=${2:-2026} shards=${3:-$(nproc)}
work=$(mktemp -d -t dda-sweep.XXXXXX)
trap 'rm -rf "$work"' EXIT
# shellcheck disable=SC2086
parallel --will-cite ${PARALLEL_OPTS:-} --halt now,fail=1 \
  "$build/bin/program_sweep" --cases "$cases" --seed "$seed" --shard {}/"$shards" --json "$work/s{}.json" \
  ::: $(seq 0 $((shards - 1)))
table=$("$build/bin/program_sweep" --merge "$work"/s*.json)
echo "$table"
echo "$table" | "$root/scripts/results-table.sh" scripts/program-sweep.sh "scripts/program-sweep.sh $cases $seed $shards"
