// The one-lane fallback of simd_lanes.hpp (targets without SSE2), forced with
// SEPAX_NO_SIMD, against the scalar code: see gauss_map_lanes_cases.hpp.
#define SEPAX_NO_SIMD 1
#include "gauss_map_lanes_cases.hpp"

TEMPLATE_TEST_CASE("gauss map lanes (no SIMD): batched arc test, lane support scan = scalar",
                   "[sat][gauss_map][lanes]", float, double) {
  CHECK(sepax::simd::Lanes<TestType>::width == 1);
  sepax::test::lanes::run_all<TestType>();
}
