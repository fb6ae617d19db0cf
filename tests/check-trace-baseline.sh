#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Each line of the baseline file is "a b n sha256": the SHA-256 of
#   dda trace --a A --b B --bits N --preload zero --from A,0 --to 0,B --format csv
# as main printed it before the restructuring of the models into libraries. Fails on the
# first configuration whose output differs, naming it.
#   usage: tests/check-trace-baseline.sh DDA BASELINE
set -euo pipefail
dda=$1 baseline=$2
n=0
while read -r a b bits want; do
  got=$("$dda" trace --a "$a" --b "$b" --bits "$bits" --preload zero --from "$a,0" --to "0,$b" --format csv | sha256sum)
  got=${got%% *}
  if [ "$got" != "$want" ]; then
    echo "baseline: dda trace --a $a --b $b --bits $bits --preload zero differs (sha256 $got, recorded $want)" >&2
    exit 1
  fi
  n=$((n + 1))
done < "$baseline"
[ "$n" -gt 0 ] || { echo "baseline: no configuration in $baseline" >&2; exit 1; }
echo "baseline: $n traces byte-identical to the recorded ones"
