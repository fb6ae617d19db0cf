#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Prints the mutants of scripts/rtl-mutants.txt for one implementation, one a line as
# name%file%anchor%replacement%text; with "sim" only those that simulation can show.
#   usage: scripts/rtl-mutants.sh small|fast [sim]
#   (scripts/assert-mutants.sh, scripts/formal-mutants.sh)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -ge 1 ] || { echo "usage: $0 small|fast [sim]" >&2; exit 2; }
impl=$1 sim=${2:-}
n=0
while IFS='%' read -r where which name file from to text; do
  case "$where" in \#*|"") continue ;; esac
  [ "$which" = both ] || [ "$which" = "$impl" ] || continue
  [ -z "$sim" ] || [ "$where" = sim+formal ] || continue  # formal-only faults show at the ports first
  echo "$name%$file%$from%$to%$text"
  n=$((n + 1))
done < "$root/scripts/rtl-mutants.txt"
[ "$n" -gt 0 ] || { echo "rtl-mutants: none for $impl" >&2; exit 1; }
