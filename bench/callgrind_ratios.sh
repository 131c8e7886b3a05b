#!/bin/sh
# Instruction counts per query (valgrind --tool=callgrind) for the two rows of
# every target (sepax_bench --list-targets): a noise-free cross-check of the
# wall-clock ratios on a shared machine.  Only the query loop is instrumented
# (client requests around it; setup and a warm-up pass run uninstrumented).
# Counts are instructions, not time: they do not see cache misses or branch
# mispredictions.
#
#   bench/callgrind_ratios.sh [BUILD_DIR] [PAIRS] [FILTER]
# FILTER keeps the targets whose line (name, workload, poses, rows) contains it.
set -eu
BUILD=${1:-build-bench}
PAIRS=${2:-32}
FILTER=${3:-}
BIN=$BUILD/bench/sepax_bench
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

# ir ROW WORKLOAD POSES -> instructions per query (cached per row)
ir() {
  key=$(printf '%s|%s|%s' "$1" "$2" "$3" | tr -c 'A-Za-z0-9' '_')
  if [ ! -f "$OUT/$key" ]; then
    f="$OUT/cg.out"
    valgrind --tool=callgrind --instr-atstart=no --callgrind-out-file="$f" \
      "$BIN" --callgrind --row "$1" --workload "$2" --poses "$3" \
      --pairs "$PAIRS" --passes 1 >"$OUT/stdout" 2>"$OUT/stderr" || { echo "-" >"$OUT/$key"; rm -f "$f"; echo "-"; return; }
    q=$(sed -n 's/^queries //p' "$OUT/stdout")
    total=$(sed -n 's/.*Collected : *//p' "$OUT/stderr" | tr -d ',')
    rm -f "$f"
    awk -v t="$total" -v q="$q" 'BEGIN { printf "%.0f", t / q }' >"$OUT/$key"
  fi
  cat "$OUT/$key"
}

echo "callgrind instructions per query, $PAIRS pairs per pose set"
"$BIN" --list-targets | grep -F -- "$FILTER" >"$OUT/targets"
while IFS="$(printf '\t')" read -r name workload poses slower faster bound value; do
  s=$(ir "$slower" "$workload" "$poses")
  f=$(ir "$faster" "$workload" "$poses")
  if [ "$s" = "-" ] || [ "$f" = "-" ]; then
    printf '  %-72s %s\n' "$name" "NOT MEASURED (a row is missing)"
    continue
  fi
  awk -v n="$name" -v s="$s" -v f="$f" -v need="$value" -v bound="$bound" 'BEGIN {
    r = s / f; ok = (bound == "at_least") ? (r >= need) : (r <= need);
    printf "  %-72s %12.0f / %10.0f Ir = %8.2f  (%s %s) %s\n", n, s, f, r, (bound == "at_least") ? ">=" : "<=", need, ok ? "met" : "MISSED" }'
done <"$OUT/targets"
