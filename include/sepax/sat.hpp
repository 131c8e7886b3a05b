// sepax/sat.hpp
//
// All three SATs behind one entry point, for code that picks the algorithm at
// run time (the sepax program, the fuzzer, the renderer):
//
//   sat::run<Policy>(SatAlgorithm::gauss_map, a, b, opt)
//
// is sat::gauss_map<Policy>(a, b, opt), and likewise for brute_force and
// traversal.  Same result type and tie-break for all three (feature.hpp).
#pragma once

#include <string_view>

#include "sat_brute_force.hpp"
#include "sat_gauss_map.hpp"
#include "sat_traversal.hpp"

namespace sepax {

enum class SatAlgorithm { brute_force, gauss_map, traversal };

inline constexpr SatAlgorithm kSatAlgorithms[] = {SatAlgorithm::brute_force, SatAlgorithm::gauss_map,
                                                  SatAlgorithm::traversal};

/// "brute_force", "gauss_map", "traversal".
inline const char* to_string(SatAlgorithm s) {
  switch (s) {
    case SatAlgorithm::brute_force:
      return "brute_force";
    case SatAlgorithm::gauss_map:
      return "gauss_map";
    case SatAlgorithm::traversal:
      return "traversal";
  }
  return "?";
}

namespace sat {

template <class Policy = policy::Plain, Number T>
SatResult<T> run(SatAlgorithm algorithm, const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b,
                 const SatOptions& opt = {}) {
  switch (algorithm) {
    case SatAlgorithm::brute_force:
      return brute_force<Policy>(a, b, opt);
    case SatAlgorithm::traversal:
      return traversal<Policy>(a, b, opt);
    case SatAlgorithm::gauss_map:
      break;
  }
  return gauss_map<Policy>(a, b, opt);
}

}  // namespace sat
}  // namespace sepax
