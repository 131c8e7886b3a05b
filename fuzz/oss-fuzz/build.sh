#!/bin/bash -eu
# Builds sepax's libFuzzer targets the way OSS-Fuzz and ClusterFuzzLite call a
# project's build.sh, from the environment they define:
#   CXX, CXXFLAGS        the compiler and its flags (sanitizers and coverage
#                        instrumentation included, e.g. -fsanitize=address
#                        -fsanitize=fuzzer-no-link)
#   LIB_FUZZING_ENGINE   the fuzzing engine to link (-fsanitize=fuzzer)
#   OUT                  where the targets, seed corpora, dictionaries and
#                        .options files go
#   WORK                 scratch for object files (default: a temporary dir)
# and, for the dependencies (header-only Eigen 3.4 and CGAL >= 5.5; GMP and
# MPFR as libraries):
#   SEPAX_DEPS_CXXFLAGS  include flags (default: -I/usr/include/eigen3)
#   SEPAX_DEPS_LIBS      link flags    (default: -lgmpxx -lgmp -lmpfr)
#   SEPAX_BUILD_JOBS     parallel compilations (default: nproc)
# Targets written to $OUT:
#   sepax_libfuzzer    bytes -> two shapes and a pose (decode_bytes)
#   sepax_case_fuzzer  the text case format (fuzz/corpus/*.case)
# each with <target>_seed_corpus.zip (built from fuzz/corpus/), a .dict and a
# .options file.  An unexplained disagreement aborts (a crash to the engine).
# The local check of this script is fuzz/oss-fuzz/test_build.sh (ctest
# fuzz/oss_fuzz_build).

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
: "${CXX:?CXX is not set}" "${LIB_FUZZING_ENGINE:?LIB_FUZZING_ENGINE is not set}" "${OUT:?OUT is not set}"
CXXFLAGS=${CXXFLAGS:-}
deps_flags=${SEPAX_DEPS_CXXFLAGS:--I/usr/include/eigen3}
deps_libs=${SEPAX_DEPS_LIBS:--lgmpxx -lgmp -lmpfr}
jobs=${SEPAX_BUILD_JOBS:-$(nproc 2>/dev/null || echo 2)}
obj=${WORK:-$(mktemp -d)}/sepax-fuzz-obj
mkdir -p "$obj" "$OUT"

# -DNDEBUG as the project's release builds; never -ffast-math (exactness).
flags="-std=c++20 -DNDEBUG -I$root/include -I$root/robust/include -I$root/fuzz/include $deps_flags"

compile() {  # source -> $obj/NAME.o
  local src=$1
  # shellcheck disable=SC2086  # CXX and the flags are word lists by convention
  $CXX $CXXFLAGS $flags -c "$root/fuzz/src/$src" -o "$obj/${src%.cpp}.o"
}

sources=(case_io.cpp check.cpp check_manifold.cpp check_posed.cpp generators.cpp libfuzzer_target.cpp case_fuzz_target.cpp)
pids=()
for src in "${sources[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do sleep 0.2; done
  compile "$src" &
  pids+=($!)
done
for pid in "${pids[@]}"; do wait "$pid"; done

core=("$obj/case_io.o" "$obj/check.o" "$obj/check_manifold.o" "$obj/check_posed.o" "$obj/generators.o")
for target in sepax_libfuzzer sepax_case_fuzzer; do
  case $target in
    sepax_libfuzzer) main=$obj/libfuzzer_target.o ;;
    sepax_case_fuzzer) main=$obj/case_fuzz_target.o ;;
  esac
  # shellcheck disable=SC2086
  $CXX $CXXFLAGS "$main" "${core[@]}" $LIB_FUZZING_ENGINE $deps_libs -o "$OUT/$target"
  rm -f "$OUT/${target}_seed_corpus.zip"
  (cd "$root/fuzz/corpus" && zip -q -j "$OUT/${target}_seed_corpus.zip" ./*.case)
  cp "$here/$target.options" "$here/$target.dict" "$OUT/"
done
echo "sepax fuzz targets in $OUT: sepax_libfuzzer sepax_case_fuzzer"
