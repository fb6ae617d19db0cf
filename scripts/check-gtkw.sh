#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Fails unless every signal a GTKWave save file shows is declared in the waveform.
#   usage: scripts/check-gtkw.sh WAVEFORM.vcd SAVEFILE.gtkw
set -euo pipefail
vcd=$1 gtkw=$2
declared=$(awk '
  $1 == "$scope" { stack[++n] = $3 }
  $1 == "$upscope" { n-- }
  $1 == "$var" {
    name = ""; for (i = 1; i <= n; i++) name = name stack[i] "."
    print name $5
  }' "$vcd" | sort -u)
missing=0 count=0
while read -r line; do
  case "$line" in ''|'['*|'@'*|'-'*) continue ;; esac
  line=${line#+\{*\} }   # an alias "+{name} " before the signal
  sig=${line%%\[*}
  count=$((count + 1))
  if ! grep -qxF "$sig" <<< "$declared"; then
    echo "check-gtkw: $gtkw shows $sig, which $vcd does not declare" >&2
    missing=1
  fi
done < "$gtkw"
[ "$count" -gt 0 ] || { echo "check-gtkw: no signal in $gtkw" >&2; exit 1; }
[ "$missing" -eq 0 ] || exit 1
echo "check-gtkw: all $count signals of $(basename "$gtkw") are in $(basename "$vcd")"
