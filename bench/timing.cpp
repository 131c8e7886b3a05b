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
}  // namespace

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

Measured measure(const Cell& c, const Row& row, double min_time, double max_pass, std::vector<Out>& outs) {
  Measured m;
  m.workload = c.workload;
  m.poses = c.poses;
  m.row = row.name;
  m.group = row.group;
  m.n = c.n;
  std::size_t np = std::min(c.pairs.size(), row.max_pairs);
  outs.assign(np, Out{});
  const auto frames = static_cast<std::size_t>(std::max(c.frames, 1));
  double t0 = now_s();
  for (std::size_t i = 0; i < np; ++i) {
    outs[i] = row.run(i);
    if (i + 1 >= kMinPairs && (i + 1) % frames == 0 && now_s() - t0 > max_pass) {
      np = i + 1;
      outs.resize(np);
      break;
    }
  }
  m.queries = static_cast<int>(np);
  for (const auto& o : outs) m.exact_fallbacks += double(o.exact_fallbacks) / double(np);
  const double first = now_s() - t0;
  const double per_pair = first / double(np);
  std::size_t chunk =
      std::clamp<std::size_t>(static_cast<std::size_t>(kChunkTime / std::max(per_pair, 1e-12)), 1, np);
  chunk = (chunk + frames - 1) / frames * frames;  // whole trajectories
  std::vector<double> best_chunk;
  for (std::size_t b = 0; b < np; b += chunk) best_chunk.push_back(HUGE_VAL);
  const double start = now_s();
  for (int rep = 0; rep < 2 || (now_s() - start < min_time && rep < 1000); ++rep) {
    double sum = 0;
    for (std::size_t b = 0, k = 0; b < np; b += chunk, ++k) {
      const std::size_t e = std::min(np, b + chunk);
      t0 = now_s();
      for (std::size_t i = b; i < e; ++i) sum += row.run(i).sep;
      best_chunk[k] = std::min(best_chunk[k], now_s() - t0);
    }
    g_sink = g_sink + sum;
  }
  double best = 0;
  for (double t : best_chunk) best += t;
  m.ns = best * 1e9 / double(np);
  // verdicts and depth errors against the exact reference
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
