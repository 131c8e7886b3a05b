// sepax/fuzz/sat_list.hpp
//
// The SATs and policies the fuzzer covers, picked up as they land:
//   sat::brute_force, sat::gauss_map             always
//   sat::traversal     (sepax/sat_traversal.hpp) when the header exists
//   policy::Robust     (sepax/robust/robust_kernel.hpp) when the header exists
#pragma once

#include <string>
#include <vector>

#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>

#if __has_include(<sepax/sat_traversal.hpp>)
#include <sepax/sat_traversal.hpp>
#define SEPAX_FUZZ_HAS_TRAVERSAL 1
#else
#define SEPAX_FUZZ_HAS_TRAVERSAL 0
#endif

#if __has_include(<sepax/robust/robust_kernel.hpp>)
#include <sepax/robust/robust_kernel.hpp>
#define SEPAX_FUZZ_HAS_ROBUST 1
#else
#define SEPAX_FUZZ_HAS_ROBUST 0
#endif

namespace sepax::fuzz {

enum class Sat { brute_force, gauss_map, traversal };

inline const char* sat_name(Sat s) {
  switch (s) {
    case Sat::brute_force: return "brute_force";
    case Sat::gauss_map: return "gauss_map";
    case Sat::traversal: return "traversal";
  }
  return "?";
}

inline std::vector<Sat> all_sats() {
  std::vector<Sat> v{Sat::brute_force, Sat::gauss_map};
  if (SEPAX_FUZZ_HAS_TRAVERSAL) v.push_back(Sat::traversal);
  return v;
}

template <class Policy, class T>
SatResult<T> run_sat(Sat s, const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b) {
  switch (s) {
    case Sat::brute_force: return sat::brute_force<Policy>(a, b);
#if SEPAX_FUZZ_HAS_TRAVERSAL
    case Sat::traversal: return sat::traversal<Policy>(a, b);
#else
    case Sat::traversal: break;
#endif
    case Sat::gauss_map: break;
  }
  return sat::gauss_map<Policy>(a, b);
}

}  // namespace sepax::fuzz
