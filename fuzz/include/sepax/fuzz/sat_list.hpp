// sepax/fuzz/sat_list.hpp
//
// The SATs and policies the fuzzer covers, picked up as they land:
//   sat::brute_force, sat::gauss_map             always
//   sat::traversal                               always (all through sat::run, sepax/sat.hpp)
//   policy::Robust     (sepax/robust/robust_kernel.hpp) when the header exists
#pragma once

#include <string>
#include <vector>

#include <sepax/sat.hpp>

#define SEPAX_FUZZ_HAS_TRAVERSAL 1

#if __has_include(<sepax/robust/robust_kernel.hpp>)
#include <sepax/robust/robust_kernel.hpp>
#define SEPAX_FUZZ_HAS_ROBUST 1
#else
#define SEPAX_FUZZ_HAS_ROBUST 0
#endif

namespace sepax::fuzz {

/// The fuzzer's name for the library's SatAlgorithm (sepax/sat.hpp).
using Sat = SatAlgorithm;

inline const char* sat_name(Sat s) { return to_string(s); }

inline std::vector<Sat> all_sats() {
  std::vector<Sat> v{Sat::brute_force, Sat::gauss_map};
  if (SEPAX_FUZZ_HAS_TRAVERSAL) v.push_back(Sat::traversal);
  return v;
}

template <class Policy, class T>
SatResult<T> run_sat(Sat s, const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b,
                     const SatOptions& opt = {}) {
  return sat::run<Policy>(s, a, b, opt);
}

}  // namespace sepax::fuzz
