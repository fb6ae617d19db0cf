#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# No function over 80 lines in the project's own C++ (model/, host/, cli/, tb/, bench/ and the
# fuzz target; tests and generated code aside): clang-tidy's readability-function-size
# over every such source of BUILD_DIR/compile_commands.json, two at a time.
#   usage: tests/check-function-size.sh BUILD_DIR          (fails naming each function)
#          tests/check-function-size.sh --planted          (passes only if a planted
#                                                           81-line function is caught)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tidy=${CLANG_TIDY:-clang-tidy}
limit=80
config="{CheckOptions: [{key: readability-function-size.LineThreshold, value: $limit}]}"
if [ "${1:-}" = "--planted" ]; then
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  { echo "int planted(int x) {"; for i in $(seq 1 $((limit + 1))); do echo "  x += $i;"; done; echo "  return x;"; echo "}"; } \
    > "$work/planted.cpp"
  got=$("$tidy" --quiet -checks='-*,readability-function-size' -config="$config" "$work/planted.cpp" -- -std=c++17 \
    2>/dev/null || true)
  if grep -q "function 'planted' exceeds" <<< "$got"; then
    echo "function-size: the planted $((limit + 1))-line function is caught"
    exit 0
  fi
  echo "function-size: the planted function was NOT caught: the check cannot fail" >&2
  exit 1
fi
build=$1
[ -f "$build/compile_commands.json" ] || { echo "function-size: no $build/compile_commands.json" >&2; exit 1; }
cd "$root"
mapfile -t files < <(git ls-files 'model/*.cpp' 'host/*.cpp' 'cli/*.cpp' 'tb/*.cpp' 'bench/*.cpp' 'tests/fuzz/*.cpp')
[ "${#files[@]}" -gt 0 ] || { echo "function-size: no sources found" >&2; exit 1; }
out=$(printf '%s\n' "${files[@]}" | xargs -P 2 -n 4 "$tidy" -p "$build" --quiet -checks='-*,readability-function-size' \
  -config="$config" 2>/dev/null | grep "warning: function" | sed "s|$root/||" || true)
if [ -n "$out" ]; then
  echo "$out" >&2
  echo "function-size: $(wc -l <<< "$out") function(s) over $limit lines (split them)" >&2
  exit 1
fi
echo "function-size: ${#files[@]} sources, no function over $limit lines"
