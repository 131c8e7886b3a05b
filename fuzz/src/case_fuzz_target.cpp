// libFuzzer target on the text case format (case.hpp): text -> read_case ->
// the checking core.  Its seeds are fuzz/corpus/*.case, the degenerate pairs
// that matter (double-sided triangles on faces, touching boxes, resolved
// findings); libFuzzer mutates their coordinates and face lists, guided by
// fuzz/oss-fuzz/sepax_case_fuzzer.dict.  A file that does not parse, or
// whose shapes are not valid convex polyhedra, is a rejected input (the
// parser and the validation must refuse it with InvalidInput, never crash).
// An unexplained disagreement aborts, so libFuzzer keeps the input; decoded
// inputs replay with `sepax fuzz --replay FILE`.
#include <cstdint>
#include <sstream>
#include <string>

#include <sepax/error.hpp>
#include <sepax/fuzz/case.hpp>
#include <sepax/fuzz/libfuzzer_check.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  sepax::fuzz::FuzzCase c;
  try {
    c = sepax::fuzz::read_case(in, "libfuzzer-input");
  } catch (const sepax::InvalidInput&) {
    return 0;  // refused by the parser, as it must be
  }
  // Keep every input fast under the sanitizers: the checking core is
  // O(E_A E_B (V_A + V_B)) in rationals on the brute force.
  if (c.a.vertices.size() > 128 || c.b.vertices.size() > 128) return 0;
  sepax::fuzz::check_or_abort(c);
  return 0;
}
