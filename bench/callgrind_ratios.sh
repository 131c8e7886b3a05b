#!/bin/sh
# Instruction counts per query (valgrind --tool=callgrind) for the rows the
# targets compare: a noise-free cross-check of the wall-clock ratios on a
# shared machine.  Only the query loop is instrumented (client requests around
# it; setup runs uninstrumented).  Counts are instructions, not time: they do
# not see cache misses or branch mispredictions.
#
#   bench/callgrind_ratios.sh [BUILD_DIR] [PAIRS]
set -eu
BUILD=${1:-build-bench}
PAIRS=${2:-32}
BIN=$BUILD/bench/sepax_bench
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

# ir ROW WORKLOAD -> instructions per query
ir() {
  f="$OUT/cg.out"
  valgrind --tool=callgrind --instr-atstart=no --callgrind-out-file="$f" \
    "$BIN" --callgrind --row "$1" --workload "$2" --poses overlapping \
    --pairs "$PAIRS" --passes 1 >"$OUT/stdout" 2>"$OUT/stderr"
  q=$(sed -n 's/^queries //p' "$OUT/stdout")
  total=$(sed -n 's/.*Collected : *//p' "$OUT/stderr" | tr -d ',')
  rm -f "$f"
  awk -v t="$total" -v q="$q" 'BEGIN { printf "%.0f", t / q }'
}

# ratio NAME SLOW_ROW FAST_ROW WORKLOAD NEED (at least)
ratio() {
  s=$(ir "$2" "$4"); f=$(ir "$3" "$4")
  awk -v n="$1" -v s="$s" -v f="$f" -v need="$5" -v op="$6" 'BEGIN {
    r = s / f; ok = (op == ">=") ? (r >= need) : (r <= need);
    printf "  %-52s %12.0f / %10.0f Ir = %8.2f  (%s %s) %s\n", n, s, f, r, op, need, ok ? "met" : "MISSED" }'
}

echo "callgrind instructions per query, overlapping poses, $PAIRS pairs"
for nd in "4 3" "8 8" "16 25" "32 50"; do
  set -- $nd
  ratio "gauss over brute, sphere$1" "brute float" "gauss float" "sphere$1" "$2" ">="
done
ratio "traversal over gauss, sphere32" "gauss float" "traversal float" sphere32 5 ">="
ratio "traversal over gauss, sphere128" "gauss float" "traversal float" sphere128 20 ">="
for n in 8 16 32 64 128 256; do
  ratio "bullet gjk+epa over robust traversal, sphere$n" "bullet gjk+epa (float)" "traversal float robust" "sphere$n" 3 ">="
done
for n in 16 32 64; do
  ratio "robust over plain gauss map, sphere$n" "gauss float robust" "gauss float" "sphere$n" 1.15 "<="
  ratio "robust over plain traversal, sphere$n" "traversal float robust" "traversal float" "sphere$n" 1.15 "<="
  ratio "traversal+manifold over traversal, sphere$n" "traversal+manifold float" "traversal float" "sphere$n" 1.30 "<="
done
