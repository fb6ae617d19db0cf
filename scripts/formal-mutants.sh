#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Every assertion written beside the logic fails on a mutated copy of the RTL under the
# formal proof (scripts/formal.sh props, bounded check from reset at AccWidth 8,
# CntWidth 4): for each assertion a fault that only it guards against, injected into a
# copy of rtl/; the proof must fail on that assertion. Both implementations take the
# shared mutants; the fast one also those of its derived registers.
#   usage: scripts/formal-mutants.sh [--impl small|fast]   (ctest formal.*.mutants)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
impl=small
if [ "${1:-}" = --impl ]; then impl=$2; shift 2; fi
case "$impl" in small|fast) ;; *) echo "formal-mutants: --impl must be small or fast" >&2; exit 2 ;; esac

# The mutants of this implementation (scripts/rtl-mutants.txt).
mapfile -t mutants < <("$root/scripts/rtl-mutants.sh" "$impl")
[ ${#mutants[@]} -gt 0 ] || exit 1
export DDA_RTL=$root/rtl
status=0
for m in "${mutants[@]}"; do
  IFS='%' read -r name file from to text <<< "$m"
  dir="$build/formal_mutants/$impl/$name"
  rm -rf "$dir"
  mkdir -p "$dir"
  "$root/scripts/rtl-files.sh" "$root/rtl/dda_core.f" | xargs cp -t "$dir/"
  grep -qF "$from" "$dir/$file" || { echo "formal-mutants: anchor not found in rtl/$file: $from" >&2; exit 1; }
  FROM=$from TO=$to perl -0pi -e 's/\Q$ENV{FROM}\E/$ENV{TO}/' "$dir/$file"
  echo "mutant $name ($file):"
  "$root/scripts/formal.sh" --impl "$impl" --acc 8 --cnt 4 --depth 8 --rtl "$dir" --expect-fail "$text" props |
    grep -v "^formal props" || status=1
done
exit $status
