// hull_compare: convex_hull against the quadratic reference builder
// (tools/reference/convex_hull_reference.hpp) on the benchmark's point sets
// (sepax_hull_bench's generator, 10^3 and 10^4 points), the hull tests'
// stress streams (tests/core/hull_point_sets.hpp) and the vertex sets of the
// fuzz corpus (fuzz/corpus/*.case): the same polytope (vertex set and faces,
// up to numbering), or the same error.  Prints every difference with both
// results' bound measures, and a summary.
//
//   hull_compare [CORPUS_DIR] [stress sets per seed, default 2000]
#include <sepax/convex_hull.hpp>

#include "hull_compare_signature.hpp"
#include "reference/convex_hull_reference.hpp"
#include "../tests/core/hull_point_sets.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace sepax;

namespace {

struct Tally {
  long sets = 0, same = 0, differ = 0;
};

template <class T>
void compare(const std::string& name, const std::vector<Vec3<T>>& pts, Tally& t) {
  ++t.sets;
  std::string a, b;
  std::optional<ConvexPolyhedron<T>> ha, hb;
  try {
    ha = convex_hull(pts);
    a = hull_compare::signature(*ha);
  } catch (const InvalidInput& e) {  // (the same error: the same code; messages may be worded apart)
    a = "InvalidInput " + std::to_string(static_cast<int>(e.code()));
  } catch (const std::exception& e) {
    a = std::string("error: ") + e.what();
  }
  try {
    hb = reference::convex_hull(pts);
    b = hull_compare::signature(*hb);
  } catch (const InvalidInput& e) {  // (the same error: the same code; messages may be worded apart)
    b = "InvalidInput " + std::to_string(static_cast<int>(e.code()));
  } catch (const std::exception& e) {
    b = std::string("error: ") + e.what();
  }
  if (a == b) {
    ++t.same;
    return;
  }
  ++t.differ;
  std::printf("DIFFERS %s (%zu points)\n", name.c_str(), pts.size());
  for (const auto* h : {&ha, &hb}) {
    if (*h) {
      std::printf("  %s: %d vertices, %d faces, height %.3g, distance %.3g (x eps)\n",
                  h == &ha ? "new" : "reference", (*h)->vertex_count(), (*h)->face_count(),
                  hull_sets::max_outside(**h, pts), hull_sets::max_distance(**h, pts));
    } else {
      std::printf("  %s: %s\n", h == &ha ? "new" : "reference", (h == &ha ? a : b).substr(0, 160).c_str());
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string corpus = argc > 1 ? argv[1] : "fuzz/corpus";
  const int stress = argc > 2 ? std::atoi(argv[2]) : 2000;
  Tally tb, tc, ts;
  for (const char* kind : {"sphere", "ball", "slab", "cylinder"})
    for (std::size_t n : {std::size_t{1000}, std::size_t{10000}}) {
      const auto p = hull_sets::bench_point_set(kind, n);
      const std::string name = std::string("bench ") + kind + " " + std::to_string(n);
      compare<double>(name + " double", p, tb);
      compare<float>(name + " float", hull_sets::to_t<float>(p), tb);
    }
  if (std::filesystem::is_directory(corpus)) {
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(corpus))
      if (e.path().extension() == ".case") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
      std::ifstream in(f);
      std::vector<Vec3<double>> pts;
      int shape = 0;
      auto flush = [&] {
        if (pts.size() >= 3) {
          const std::string name = f.filename().string() + " shape " + std::to_string(shape);
          compare<double>(name + " double", pts, tc);
          compare<float>(name + " float", hull_sets::to_t<float>(pts), tc);
        }
        pts.clear();
        ++shape;
      };
      for (std::string line; std::getline(in, line);) {
        if (line.rfind("shape", 0) == 0) flush();
        if (line.rfind("v ", 0) == 0) {
          std::istringstream ls(line.substr(2));
          double x = 0, y = 0, z = 0;
          if (ls >> x >> y >> z) pts.emplace_back(x, y, z);
        }
      }
      flush();
    }
  }
  for (unsigned seed : {1u, 2u}) {
    std::mt19937 rng(seed);
    for (int it = 0; it < stress; ++it) {
      const auto p = hull_sets::random_point_set(rng, it % 9);
      const std::string name = "stress seed " + std::to_string(seed) + " it. " + std::to_string(it);
      compare<double>(name + " double", p, ts);
      compare<float>(name + " float", hull_sets::to_t<float>(p), ts);
    }
  }
  std::printf("bench sets: %ld, same %ld, differ %ld\n", tb.sets, tb.same, tb.differ);
  std::printf("corpus sets: %ld, same %ld, differ %ld\n", tc.sets, tc.same, tc.differ);
  std::printf("stress sets: %ld, same %ld, differ %ld\n", ts.sets, ts.same, ts.differ);
  return tb.differ + tc.differ + ts.differ == 0 ? 0 : 1;
}
