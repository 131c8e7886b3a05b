// The Gauss map's SIMD (SSE2) paths against the scalar code: see
// gauss_map_lanes_cases.hpp.
#include "gauss_map_lanes_cases.hpp"

static_assert(!sepax::HasMinkowskiFaces<sepax::test::lanes::ScalarArcKernel<float>>);
static_assert(sepax::HasMinkowskiFaces<sepax::PlainKernel<float>>);
static_assert(sepax::HasMinkowskiFaces<sepax::PlainKernel<double>>);

TEMPLATE_TEST_CASE("gauss map lanes: batched arc test, lane support scan = scalar", "[sat][gauss_map][lanes]",
                   float, double) {
#if defined(__SSE2__)
  CHECK(sepax::simd::Lanes<TestType>::width > 1);
#endif
  sepax::test::lanes::run_all<TestType>();
}
