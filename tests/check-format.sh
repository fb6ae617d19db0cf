#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The form of the sources: every C++ file git tracks is as clang-format (.clang-format)
# writes it, and every source file (C++, C headers, Verilog and SystemVerilog, file lists,
# CMake, shell, Python) carries the SPDX licence line in its first lines (data files such
# as tests/data/*.csv do not).
#   usage: tests/check-format.sh [clang-format|spdx]     (ctest format.*)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
what=${1:-clang-format}
mapfile -t files < <(git ls-files)
case "$what" in
  clang-format)
    cf=${CLANG_FORMAT:-clang-format}
    mapfile -t cxx < <(printf '%s\n' "${files[@]}" | grep -E '\.(cpp|hpp)$')
    [ ${#cxx[@]} -gt 0 ] || { echo "format: no C++ file found" >&2; exit 1; }
    "$cf" --dry-run --Werror "${cxx[@]}"
    echo "format: ${#cxx[@]} C++ files as clang-format writes them" ;;
  spdx)
    missing=0 n=0
    for f in "${files[@]}"; do
      case "$f" in
        *.cpp|*.hpp|*.c|*.h|*.v|*.vh|*.sv|*.py|*.f|*.vlt|*.sh|*.cmake|*CMakeLists.txt|scripts/*|.ci/*|*.gtkw|.clang-format) ;;
        *) continue ;;
      esac
      n=$((n + 1))
      if ! head -n 3 "$f" | grep -q 'SPDX-License-Identifier: Apache-2.0'; then
        echo "spdx: $f has no SPDX-License-Identifier line" >&2
        missing=1
      fi
    done
    [ "$missing" -eq 0 ] || exit 1
    echo "spdx: all $n source files carry the licence line" ;;
  *) echo "usage: $0 [clang-format|spdx]" >&2; exit 2 ;;
esac
