#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The firmware header's C example (fw/examples/line_entry.c) compiles as C99 with
# -Wall -Wextra -pedantic and no warning, and packs the same entry words for a line as
# `dda entries --line` prints, on lines in every direction, of two and three axes, one
# of the counters' full length; a line longer than one entry is refused.
#   usage: tests/check-fw-example.sh CC DDA FW_DIR
set -euo pipefail
[ $# -eq 3 ] || { echo "usage: $0 CC DDA FW_DIR" >&2; exit 2; }
cc=$1 dda=$2 fw=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$cc" -std=c99 -Wall -Wextra -pedantic -Werror -I "$fw" "$fw/examples/line_entry.c" -o "$tmp/line_entry"
n=0
for d in "17 -5 0" "-3 40 0" "1 0 0" "0 -1 0" "-7 -7 0" "12 5 -9" "0 0 250" "131071 -3 2"; do
  read -r dx dy dz <<<"$d"
  want=$("$dda" entries --line --from 0,0,0 --to "$dx,$dy,$dz" | sed 's/^[^:]*: //')
  got=$("$tmp/line_entry" "$dx" "$dy" "$dz")
  [ "$(wc -l <<<"$want")" = 1 ] || { echo "check-fw-example: dda made more than one piece of $d" >&2; exit 1; }
  [ "$got" = "$want" ] || { printf 'check-fw-example: line to %s\n  C:   %s\n  dda: %s\n' "$d" "$got" "$want" >&2; exit 1; }
  n=$((n + 1))
done
if "$tmp/line_entry" 131072 0 0 2>/dev/null; then echo "check-fw-example: a line of 2^17 steps was packed" >&2; exit 1; fi
echo "check-fw-example: $n lines packed as dda entries prints them"
