// Timing the rows of one cell, and their answers judged against the exact
// reference.
//
// A first pass of each row over the pairs records its answers (and warms up).
// Then the pairs are cut into consecutive chunks of about 1 ms (whole
// trajectories for trajectory cells, so a cache always replays its trajectory
// from the start).  The rows are timed in rounds, about 10 ms of passes of
// every row per round, so that rows compared by a target run under the same
// conditions on a shared machine (a busy sibling hyperthread slows every row
// of the round, not one row's whole measurement); every chunk keeps its
// minimum time, and a row
// stops after at least two passes and min_time seconds.  ns/query = sum of
// the chunk minima / pairs.  On a loaded machine a 1 ms chunk often runs
// inside one scheduler slice, so the minimum is the undisturbed time.
#pragma once

#include <string>
#include <vector>

#include "rows.hpp"

namespace bench {

struct Measured {
  std::string workload, poses, row, group;
  int n = 0;
  double ns = 0;                        // ns per query
  double ratio = 0;                     // ns / the baseline's ns in the same cell
  int queries = 0;                      // pairs per pass
  int disagree = 0;                     // verdicts differing from the exact reference
  int failed = 0;                       // no answer
  int depth_count = 0;                  // overlapping pairs (both agree) with a depth
  double depth_med = 0, depth_max = 0;  // |depth - exact depth|
  double exact_fallbacks = 0;           // per query (robust rows; first pass)
  std::string same_as;                  // a row whose answers this row must reproduce exactly
  int differences = 0;                  // pairs whose verdict, feature or separation differ from same_as's
};

/// Times the rows on c; outs[r] receives row r's answers.  A slow row stops
/// its first pass after max_pass seconds (and at least 16 pairs) and is timed
/// on that prefix.
std::vector<Measured> measure_cell(const Cell& c, const std::vector<const Row*>& rows, double min_time,
                                   double max_pass, std::vector<std::vector<Out>>& outs);

/// Pairs whose verdict, feature or separation differ between two rows' answers.
int count_differences(const std::vector<Out>& a, const std::vector<Out>& b);

double now_s();

/// Keeps results from being optimised away.
extern volatile double g_sink;

}  // namespace bench
