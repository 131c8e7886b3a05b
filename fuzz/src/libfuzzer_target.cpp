// libFuzzer target: bytes -> hull pair + pose -> the checking core.
//
// Build (clang only):
//   cmake -S . -B build-libfuzzer -G Ninja -DCMAKE_CXX_COMPILER=clang++-14 \
//         -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSEPAX_LIBFUZZER=ON
//   cmake --build build-libfuzzer --target sepax_libfuzzer -j2
// Run for 10 minutes, seeded with the corpus (libFuzzer writes new inputs to
// the first directory, so give it a scratch copy):
//   mkdir -p /tmp/lf-corpus && ./build-libfuzzer/fuzz/sepax_libfuzzer \
//       -max_total_time=600 -timeout=30 -rss_limit_mb=4096 -max_len=256 -len_control=0 /tmp/lf-corpus
//
// An unexplained disagreement aborts (so libFuzzer saves the crashing input);
// ASan/UBSan report memory errors and undefined behaviour; -timeout catches hangs.
#include <cstdint>

#include <sepax/fuzz/libfuzzer_check.hpp>
#include <sepax/fuzz/generators.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const sepax::fuzz::FuzzCase c = sepax::fuzz::decode_bytes(data, size);
  sepax::fuzz::check_or_abort(c);
  return 0;
}
