#!/usr/bin/env bash
# Runs the golden-driven Icarus bench of dda_core (tb/icarus/dda_core_tb.v).
#
#   usage: scripts/icarus-bench.sh [options] BUILD_DIR
#     --a A --b B --bits N      the arc (default the paper's example: 10 6 4)
#     --preload zero|half       accumulator preload (default zero)
#     --from X,Y --to X,Y       end points (default a,0 and 0,b)
#     --ce-random SEED          ce_i from an LFSR instead of always high
#     --corrupt-iter K          flip the lowest bit of one expected value (--corrupt-field,
#                               default u_int_x.jr_q) in iteration K of expect.hex: the
#                               bench must then fail with a MISMATCH of exactly that
#                               register at iteration K; this script exits 0 only if it did
#     --corrupt-field NAME      register to corrupt (a name of the expect.hex header)
#     --out DIR                 work directory (default BUILD_DIR/rtl_bench/<arc>)
#     --gen PATH                gen_core_vectors (default BUILD_DIR/tb/gen_core_vectors)
#
# Without --corrupt-iter it exits 0 only if vvp exited 0 and printed the PASS line.
# Needs gen_core_vectors built: make -C BUILD_DIR gen_core_vectors.
# Registered in ctest (tests/rtl_checks.cmake) as rtl.icarus_*.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
iverilog=${IVERILOG:-iverilog}
vvp=${VVP:-vvp}

a=10 b=6 bits=4 preload=zero from="" to="" ce_random="" corrupt_iter="" corrupt_field=u_int_x.jr_q
out="" gen="" build=""
usage() { sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
while [ $# -gt 0 ]; do
  case "$1" in
    --a) a=$2; shift 2 ;;
    --b) b=$2; shift 2 ;;
    --bits) bits=$2; shift 2 ;;
    --preload) preload=$2; shift 2 ;;
    --from) from=$2; shift 2 ;;
    --to) to=$2; shift 2 ;;
    --ce-random) ce_random=$2; shift 2 ;;
    --corrupt-iter) corrupt_iter=$2; shift 2 ;;
    --corrupt-field) corrupt_field=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --gen) gen=$2; shift 2 ;;
    -h|--help) usage ;;
    -*) echo "icarus-bench: unknown option $1" >&2; usage ;;
    *) [ -z "$build" ] || usage; build=$1; shift ;;
  esac
done
[ -n "$build" ] || usage
gen=${gen:-$build/tb/gen_core_vectors}
tag="a${a}_b${b}_n${bits}_${preload}${from:+_from${from/,/-}}${to:+_to${to/,/-}}"
tag+="${ce_random:+_ce${ce_random}}${corrupt_iter:+_corrupt${corrupt_iter}}"
out=${out:-$build/rtl_bench/$tag}
[ -x "$gen" ] || { echo "icarus-bench: $gen not found: make -C $build gen_core_vectors" >&2; exit 1; }
mkdir -p "$out"

gen_args=(--a "$a" --b "$b" --bits "$bits" --preload "$preload" --out-dir "$out")
[ -z "$from" ] || gen_args+=(--from "$from")
[ -z "$to" ] || gen_args+=(--to "$to")
"$gen" "${gen_args[@]}"

if [ -n "$corrupt_iter" ]; then
  # Field index of the register in the header comment "// fields left to right ...".
  idx=$(awk -v f="$corrupt_field" '/^\/\/ fields left to right/ {
          for (i = 8; i <= NF; i++) { n = $i; sub(/\(.*/, "", n); if (n == f) { print i - 7; exit } } }' \
        "$out/expect.hex")
  [ -n "$idx" ] || { echo "icarus-bench: no field $corrupt_field in expect.hex" >&2; exit 1; }
  awk -v k="$corrupt_iter" -v f="$idx" -v name="$corrupt_field" 'BEGIN { FS = OFS = "_"; hex = "0123456789abcdef" }
    /^\/\// { print; next }
    { if (++n == k) {
        d = substr($f, length($f), 1); v = index(hex, d) - 1; v = (v % 2 == 0) ? v + 1 : v - 1
        old = $f; $f = substr($f, 1, length($f) - 1) substr(hex, v + 1, 1)
        printf "icarus-bench: corrupted iteration %d %s: %s -> %s\n", k, name, old, $f > "/dev/stderr"
        done = 1 }
      print }
    END { if (!done) exit 1 }' "$out/expect.hex" > "$out/expect.hex.tmp" ||
    { echo "icarus-bench: expect.hex has fewer than $corrupt_iter iterations" >&2; exit 1; }
  mv "$out/expect.hex.tmp" "$out/expect.hex"
fi

"$iverilog" -g2012 -I "$root/rtl" -o "$out/sim.vvp" "$root/tb/icarus/dda_core_tb.v" "$root"/rtl/dda_*.v
plusargs=("+vectors=$out")
[ -z "$ce_random" ] || plusargs+=("+ce_random=$ce_random")
set +e
"$vvp" -n "$out/sim.vvp" "${plusargs[@]}" 2>&1 | tee "$out/vvp.log"
rc=${PIPESTATUS[0]}
set -e

if [ -z "$corrupt_iter" ]; then
  if [ "$rc" -eq 0 ] && grep -q '^PASS: dda_core_tb' "$out/vvp.log"; then exit 0; fi
  echo "icarus-bench: FAIL (vvp exit $rc, log $out/vvp.log)" >&2
  exit 1
fi
# Corrupted run: must fail, and for the corrupted register at that iteration only.
re="^MISMATCH iteration $corrupt_iter cycle [0-9]+: ${corrupt_field//./\\.} expected"
if [ "$rc" -ne 0 ] && grep -Eq "$re" "$out/vvp.log" && [ "$(grep -c '^MISMATCH' "$out/vvp.log")" -eq 1 ]; then
  echo "icarus-bench: PASS: the corrupted expected value was detected (vvp exit $rc)"
  exit 0
fi
echo "icarus-bench: FAIL: expected exactly one MISMATCH of $corrupt_field at iteration $corrupt_iter and a non-zero exit (vvp exit $rc)" >&2
exit 1
