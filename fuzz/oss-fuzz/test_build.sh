#!/bin/bash
# The local check of the OSS-Fuzz / ClusterFuzzLite build (ctest
# fuzz/oss_fuzz_build): runs fuzz/oss-fuzz/build.sh with the variables
# OSS-Fuzz defines, set to a local clang with libFuzzer (ASan + UBSan, as
# OSS-Fuzz's default sanitizers), into a temporary $OUT; checks the outputs
# (targets, seed corpus zips, dictionaries, options); then runs every target
# for a few seconds on its unzipped seed corpus with the options of its
# .options file.  Fails when the build fails, an output is missing, or a
# target crashes (sanitizer report, abort on an unexplained disagreement,
# timeout, leak): libFuzzer's non-zero exit.  A self-check first shows that
# the runner does fail on a target that crashes.
#
#   test_build.sh CXX [SECONDS]     e.g. test_build.sh clang++-14 5
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
cxx=${1:?usage: test_build.sh CXX [SECONDS]}
seconds=${2:-5}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

export CXX=$cxx
export CXXFLAGS="-O1 -gline-tables-only -fno-omit-frame-pointer -fsanitize=address,undefined \
-fno-sanitize-recover=undefined -fsanitize=fuzzer-no-link"
export LIB_FUZZING_ENGINE=-fsanitize=fuzzer
export OUT=$tmp/out WORK=$tmp/work
mkdir -p "$OUT" "$WORK"

# libFuzzer flags from a target's .options file ([libfuzzer] key = value),
# the dictionary made absolute.
options_of() {
  local opts=$1 line key value
  while IFS= read -r line; do
    [[ $line =~ ^[[:space:]]*([a-z_]+)[[:space:]]*=[[:space:]]*(.*[^[:space:]])[[:space:]]*$ ]] || continue
    key=${BASH_REMATCH[1]} value=${BASH_REMATCH[2]}
    [ "$key" = dict ] && value=$(dirname "$opts")/$value
    printf -- '-%s=%s\n' "$key" "$value"
  done <"$opts"
}

# Run target $1 for $seconds on its seed corpus zip; 0 when libFuzzer exits
# cleanly after executing inputs.
run_target() {
  local target=$1 dir
  dir=$tmp/run-$(basename "$target")
  mkdir -p "$dir/corpus"
  unzip -q -o "${target}_seed_corpus.zip" -d "$dir/corpus"
  local flags=()
  [ -f "$target.options" ] && mapfile -t flags < <(options_of "$target.options")
  echo "== $(basename "$target") ${flags[*]} -max_total_time=$seconds (corpus: $(ls "$dir/corpus" | wc -l) files)"
  local status=0
  "$target" "${flags[@]}" -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="$dir/" \
    "$dir/corpus" >"$dir/log" 2>&1 || status=$?
  tail -n 25 "$dir/log"
  if [ "$status" -ne 0 ]; then
    echo "FAIL: $(basename "$target") exited with $status"
    return 1
  fi
  local runs
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$dir/log" | tail -n 1)
  if [ -z "$runs" ] || [ "$runs" -lt 1 ]; then
    echo "FAIL: $(basename "$target") executed no input"
    return 1
  fi
  echo "ok: $(basename "$target"): $runs inputs executed"
}

# Self-check: a target that aborts on the input "crash" must fail the runner.
cat >"$tmp/crash.cpp" <<'CPP'
#include <cstdint>
#include <cstdlib>
#include <cstring>
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* d, std::size_t n) {
  if (n >= 5 && std::memcmp(d, "crash", 5) == 0) std::abort();
  return 0;
}
CPP
# shellcheck disable=SC2086
$CXX -fsanitize=fuzzer "$tmp/crash.cpp" -o "$tmp/crash_fuzzer"
(cd "$tmp" && printf 'crash' >seed && zip -q crash_fuzzer_seed_corpus.zip seed)
if run_target "$tmp/crash_fuzzer" >"$tmp/selfcheck.log" 2>&1; then
  cat "$tmp/selfcheck.log"
  echo "FAIL: the runner did not notice a crashing target"
  exit 1
fi
echo "self-check: a crashing target fails the runner"

bash "$root/fuzz/oss-fuzz/build.sh"

status=0
corpus_files=$(ls "$root"/fuzz/corpus/*.case | wc -l)
for t in sepax_libfuzzer sepax_case_fuzzer; do
  for f in "$t" "${t}_seed_corpus.zip" "$t.options" "$t.dict"; do
    [ -e "$OUT/$f" ] || { echo "FAIL: build.sh did not write \$OUT/$f"; status=1; }
  done
  [ -x "$OUT/$t" ] || { echo "FAIL: \$OUT/$t is not executable"; status=1; }
  n=$(unzip -Z1 "$OUT/${t}_seed_corpus.zip" | wc -l)
  [ "$n" -eq "$corpus_files" ] || { echo "FAIL: ${t}_seed_corpus.zip has $n files, fuzz/corpus $corpus_files"; status=1; }
done
[ "$status" -eq 0 ] || exit 1
for t in sepax_libfuzzer sepax_case_fuzzer; do
  run_target "$OUT/$t" || status=1
done
exit "$status"
