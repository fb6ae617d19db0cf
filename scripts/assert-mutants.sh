#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The RTL's assertions fire: for each assertion a mutant (a fault injected into a copy of
# rtl/) on which the paper's vector set must end, under Icarus and under Verilator --assert, with the
# assertion that guards against that fault (not with a vector MISMATCH: each fault
# changes nothing before the edge where its assertion fires).
# --impl fast runs the same mutants on the fast implementation, and the mutants of its
# own assertions (its derived registers equal what they are derived from).
#   usage: scripts/assert-mutants.sh [--impl small|fast] VECTOR_SET_DIR
#   (ctest rtl.assertions_fire, rtl.fast.assertions_fire)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
impl=small
if [ "${1:-}" = --impl ]; then impl=$2; shift 2; fi
[ $# -eq 1 ] || { echo "usage: $0 [--impl small|fast] VECTOR_SET_DIR" >&2; exit 2; }
case "$impl" in small|fast) ;; *) echo "assert-mutants: --impl must be small or fast" >&2; exit 2 ;; esac
set_dir=$1

# The mutants of this implementation (scripts/rtl-mutants.txt).
mapfile -t mutants < <("$root/scripts/rtl-mutants.sh" "$impl" sim)
[ ${#mutants[@]} -gt 0 ] || exit 1
status=0
for m in "${mutants[@]}"; do
  IFS='%' read -r name file from to message <<< "$m"
  dir="$build/assert_mutants/$impl/$name"
  rm -rf "$dir"
  mkdir -p "$dir"
  # The sources of the file list, and the headers they include.
  "$root/scripts/rtl-files.sh" "$root/rtl/dda_core.f" | xargs cp -t "$dir/"
  cp "$root"/rtl/*.vh "$dir/"
  grep -qF "$from" "$dir/$file" || { echo "assert-mutants: anchor not found in rtl/$file: $from" >&2; exit 1; }
  FROM=$from TO=$to perl -0pi -e 's/\Q$ENV{FROM}\E/$ENV{TO}/' "$dir/$file"
  echo "mutant $name ($file):"
  "$root/scripts/vector-bench.sh" --impl "$impl" --rtl "$dir" --expect "$message" "$set_dir" || status=1
done
exit $status
