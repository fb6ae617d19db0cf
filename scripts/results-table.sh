#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Writes a generated table (standard input) into docs/results.md between the markers
# "<!-- BEGIN GENERATED: NAME -->" and "<!-- END GENERATED: NAME -->", after a line that
# names the command and the date. Used by the sweep scripts.
#   usage: scripts/results-table.sh NAME "COMMAND" < TABLE
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -eq 2 ] || { echo "usage: $0 NAME COMMAND < TABLE" >&2; exit 2; }
name=$1 cmd=$2
table=$(cat)
doc="$root/docs/results.md"
begin="<!-- BEGIN GENERATED: $name -->"
end="<!-- END GENERATED: $name -->"
grep -qF "$begin" "$doc" || { echo "results-table: $doc has no $begin marker" >&2; exit 1; }
tmp=$(mktemp)
awk -v b="$begin" -v e="$end" -v t="$table" -v cmd="$cmd" '
  $0 == b { print; print "Command: `" cmd "`, " strftime("%Y-%m-%d") "."; print ""; print t; skip = 1; next }
  $0 == e { skip = 0 }
  !skip { print }' "$doc" > "$tmp"
mv "$tmp" "$doc"
echo "wrote the table into docs/results.md"
