#include "timing.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace bench {

volatile double g_sink = 0;

namespace {
constexpr std::size_t kMinPairs = 16;
constexpr double kChunkTime = 0.001;
constexpr double kRoundTime = 0.01;  // a row's share of one round of interleaved timing
}  // namespace

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

namespace {

// One row's timing state: its pairs, chunk length and the best time of each chunk.
struct Timing {
  const Row* row = nullptr;
  std::size_t np = 0, chunk = 1;
  std::vector<double> best_chunk;
  int passes = 0;
  double spent = 0;  // seconds in timed passes
};

// The first pass over the pairs: answers (and the warm-up).  A slow row stops
// after max_pass seconds and at least kMinPairs pairs (whole trajectories).
Timing first_pass(const Cell& c, const Row& row, double max_pass, std::vector<Out>& outs) {
  Timing t;
  t.row = &row;
  t.np = std::min(c.pairs.size(), row.max_pairs);
  outs.assign(t.np, Out{});
  const auto frames = static_cast<std::size_t>(std::max(c.frames, 1));
  const double t0 = now_s();
  for (std::size_t i = 0; i < t.np; ++i) {
    outs[i] = row.run(i);
    if (i + 1 >= kMinPairs && (i + 1) % frames == 0 && now_s() - t0 > max_pass) {
      t.np = i + 1;
      outs.resize(t.np);
      break;
    }
  }
  const double per_pair = (now_s() - t0) / double(t.np);
  t.chunk =
      std::clamp<std::size_t>(static_cast<std::size_t>(kChunkTime / std::max(per_pair, 1e-12)), 1, t.np);
  t.chunk = (t.chunk + frames - 1) / frames * frames;  // whole trajectories
  for (std::size_t b = 0; b < t.np; b += t.chunk) t.best_chunk.push_back(HUGE_VAL);
  return t;
}

// One timed pass over a row's chunks, each chunk keeping its best time.
void timed_pass(Timing& t) {
  double sum = 0;
  const double start = now_s();
  for (std::size_t b = 0, k = 0; b < t.np; b += t.chunk, ++k) {
    const std::size_t e = std::min(t.np, b + t.chunk);
    const double t0 = now_s();
    for (std::size_t i = b; i < e; ++i) sum += t.row->run(i).sep;
    t.best_chunk[k] = std::min(t.best_chunk[k], now_s() - t0);
  }
  g_sink = g_sink + sum;
  t.spent += now_s() - start;
  ++t.passes;
}

// The row's figures: time from the chunk minima, verdicts and depth errors
// against the exact reference (posed rows against the posed input's).
Measured judge(const Cell& c, const Timing& t, const std::vector<Out>& outs) {
  const Row& row = *t.row;
  Measured m;
  m.workload = c.workload;
  m.poses = c.poses;
  m.row = row.name;
  m.group = row.group;
  m.n = c.n;
  const std::size_t np = t.np;
  m.queries = static_cast<int>(np);
  for (const auto& o : outs) m.exact_fallbacks += double(o.exact_fallbacks) / double(np);
  double best = 0;
  for (double x : t.best_chunk) best += x;
  m.ns = best * 1e9 / double(np);
  // (posed rows against the posed input's reference)
  const bool posed = row.name.find(" posed") != std::string::npos;
  std::vector<double> err;
  for (std::size_t i = 0; i < np; ++i) {
    const auto& p = c.pairs[i];
    const bool ref_overlap = posed ? p.ref_posed_overlap : p.ref_overlap;
    const double ref_sep = posed ? p.ref_posed_sep : p.ref_sep;
    if (outs[i].failed) {
      ++m.failed;
      continue;
    }
    if (outs[i].overlap != ref_overlap) {
      ++m.disagree;
      std::fprintf(stderr, "[%s %s] %s: pair %zu says %s, exact says %s (exact separation %.17g)\n",
                   c.workload.c_str(), c.poses.c_str(), row.name.c_str(), i,
                   outs[i].overlap ? "overlap" : "separated", ref_overlap ? "overlap" : "separated", ref_sep);
      continue;
    }
    if (ref_overlap && !std::isnan(outs[i].sep)) err.push_back(std::abs(outs[i].sep - ref_sep));
  }
  m.depth_count = static_cast<int>(err.size());
  if (!err.empty()) {
    std::sort(err.begin(), err.end());
    m.depth_med = err[err.size() / 2];
    m.depth_max = err.back();
  }
  return m;
}

}  // namespace

std::vector<Measured> measure_cell(const Cell& c, const std::vector<const Row*>& rows, double min_time,
                                   double max_pass, std::vector<std::vector<Out>>& outs) {
  outs.assign(rows.size(), {});
  std::vector<Timing> timings;
  for (std::size_t r = 0; r < rows.size(); ++r) timings.push_back(first_pass(c, *rows[r], max_pass, outs[r]));
  // Rounds: every row still timing runs passes for about kRoundTime (at least
  // one); a row stops after at least two passes and min_time seconds (or 1000
  // passes).  Consecutive passes of a row within a round keep its caches and
  // branch history warm, as the minimum over repetitions assumes.
  auto timing = [min_time](const Timing& t) {
    return t.passes < 2 || (t.spent < min_time && t.passes < 1000);
  };
  for (bool more = true; more;) {
    more = false;
    for (auto& t : timings) {
      const double round_start = t.spent;
      while (timing(t) && (t.spent == round_start || t.spent - round_start < kRoundTime)) {
        timed_pass(t);
        more = true;
      }
    }
  }
  std::vector<Measured> out;
  for (std::size_t r = 0; r < rows.size(); ++r) out.push_back(judge(c, timings[r], outs[r]));
  return out;
}

int count_differences(const std::vector<Out>& a, const std::vector<Out>& b) {
  int d = 0;
  const std::size_t n = std::min(a.size(), b.size());
  for (std::size_t i = 0; i < n; ++i) {
    const bool same_sep = a[i].sep == b[i].sep || (std::isnan(a[i].sep) && std::isnan(b[i].sep));
    if (a[i].overlap != b[i].overlap || a[i].feature != b[i].feature || !same_sep) ++d;
  }
  return d + static_cast<int>(std::max(a.size(), b.size()) - n);
}

}  // namespace bench
