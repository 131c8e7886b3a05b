// A row of the benchmark: one method run on every pair of a cell.
//
// Names: every sepax row runs policy::Robust unless its name says "plain"
// (mpq rows are exact by their number type).  A name says what the query
// includes:
//   posed     prepared shapes in their local frames and a world pose per
//             shape and query (the pose's cost is in the row);  without it, B
//             is pre-posed once at setup and A is in its local frame
//   manifold  contact_manifold on the SAT's result ("traversal+manifold")
//   margin    SatOptions::margin = 2% of the larger shape's extent, early exit
//   cached    a SatCache per pair (per trajectory), warm from the previous step
// Peers say "(float)"/"(double)" for their scalar type.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "workloads.hpp"

namespace bench {

struct Out {
  bool overlap = false;
  double sep = 0;                          // signed separation (< 0: penetration depth); NaN if none
  bool failed = false;                     // the method gave no answer (counted, not timed differently)
  std::array<int, 3> feature{-1, -1, -1};  // sepax rows: feature type, a, b
  std::int64_t exact_fallbacks = 0;  // robust rows: decisions the float filters left to exact arithmetic
};

struct Row {
  std::string name;
  std::string group;                                     // "sepax" or "peer"
  std::function<Out(std::size_t)> run;                   // the query of pair i
  std::size_t max_pairs = static_cast<std::size_t>(-1);  // slow rows run on a prefix of the pairs
};

/// sepax's rows for a cell (sepax_rows.cpp); the rows hold pointers into c.
std::vector<Row> sepax_rows(Cell& c);
/// sepax's exact-type rows (reference.cpp).
std::vector<Row> exact_rows(Cell& c);
/// Bullet's, libccd's and FCL's rows (peers.cpp), those built in.
std::vector<Row> peer_rows(Cell& c);

/// The plain float traversal's mean walk counters over a cell's pairs (one line).
std::string traversal_counters(const Cell& c);

/// Sum of contact points built by manifold rows: a side effect that keeps the
/// manifolds from being optimised away.
extern std::size_t g_contact_points;

}  // namespace bench
