// The one-lane fallback of simd_ops.hpp (targets without SSE2), forced with
// SEPAX_NO_SIMD: posing, which otherwise derives planes and maps vertices a
// few at a time in SSE2 lanes, must still give bit for bit what
// with_vertices gives, and every posed query what it returns on the
// pre-posed pair (the cases of posed_query_test.cpp, compiled without SIMD).
#define SEPAX_NO_SIMD 1
#include "core/posed_query_test.cpp"
