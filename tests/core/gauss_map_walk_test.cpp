// GaussMapWalk: the per-hull walk data of the traversal SAT.  Here: the probe
// vertices (farthest point sampling on the vertex graph) that let a face skip
// its hill climb (sat_traversal.hpp, probe_below_best).
#include <catch2/catch.hpp>

#include <sepax/gauss_map_walk.hpp>
#include <sepax/sat_traversal.hpp>
#include <sepax/shapes.hpp>

#include "traversal_shapes.hpp"

#include <algorithm>
#include <set>

using namespace sepax;

namespace {

// Hop distances from the set `from` over the walk's vertex adjacency (BFS).
std::vector<int> hops(const GaussMapWalk& w, const std::vector<int>& from) {
  std::vector<int> d(static_cast<std::size_t>(w.vertex_count()), -1);
  std::vector<int> queue;
  for (int v : from) {
    d[static_cast<std::size_t>(v)] = 0;
    queue.push_back(v);
  }
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const int v = queue[i];
    for (int j = w.adj_begin(v); j < w.adj_end(v); ++j) {
      const int u = w.adj_vertex(j);
      if (d[static_cast<std::size_t>(u)] < 0) {
        d[static_cast<std::size_t>(u)] = d[static_cast<std::size_t>(v)] + 1;
        queue.push_back(u);
      }
    }
  }
  return d;
}

// The documented rule, checked from scratch: vertex 0 first, then each time
// the lowest-index vertex among those furthest from the probes so far, until
// probe_count(V) (V / 8 within [kMinProbes, kMaxProbes], at most V) are chosen.
void check_probes(const GaussMapWalk& w) {
  const auto& p = w.probes();
  const int nv = w.vertex_count();
  REQUIRE(static_cast<int>(p.size()) == GaussMapWalk::probe_count(nv));
  REQUIRE(static_cast<int>(p.size()) <= GaussMapWalk::kMaxProbes);
  REQUIRE(p.front() == 0);
  CHECK(std::set<int>(p.begin(), p.end()).size() == p.size());
  for (std::size_t k = 1; k < p.size(); ++k) {
    const std::vector<int> chosen(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(k));
    const auto d = hops(w, chosen);
    const int far = *std::max_element(d.begin(), d.end());
    const int first_far = static_cast<int>(std::find(d.begin(), d.end(), far) - d.begin());
    INFO("probe " << k << " of " << p.size());
    CHECK(far > 0);
    CHECK(p[k] == first_far);
  }
}

}  // namespace

TEST_CASE("probes: probe_count scales with the vertex count within its bounds", "[walk][probes]") {
  CHECK(GaussMapWalk::probe_count(4) == 4);
  CHECK(GaussMapWalk::probe_count(16) == 16);
  CHECK(GaussMapWalk::probe_count(100) == GaussMapWalk::kMinProbes);
  CHECK(GaussMapWalk::probe_count(128) == 16);
  CHECK(GaussMapWalk::probe_count(192) == 24);
  CHECK(GaussMapWalk::probe_count(256) == GaussMapWalk::kMaxProbes);
  CHECK(GaussMapWalk::probe_count(100000) == GaussMapWalk::kMaxProbes);
}

TEST_CASE("probes: farthest point sampling on the vertex graph, probe_count of them", "[walk][probes]") {
  std::mt19937_64 rng(5);
  for (int n : {4, 8, 12, 16, 17, 32, 64, 128}) {
    const auto hull = test::sphere_hull(rng, n);
    const GaussMapWalk w(hull);
    INFO("sphere hull of " << n << " points, " << hull.vertex_count() << " vertices");
    check_probes(w);
    if (hull.vertex_count() > GaussMapWalk::kMinProbes) {
      // spread: every vertex is near a probe (a hull of N points on a sphere
      // has a graph diameter of about sqrt(N) hops)
      const auto d = hops(w, w.probes());
      CHECK(*std::max_element(d.begin(), d.end()) <= 3);
    }
  }
  // more than 16 probes on larger shapes (200 and 256 vertices)
  for (int n : {100, 128}) {
    const auto s = shapes::prism<double>(n, 1.0, 1.0);
    const GaussMapWalk w(s);
    INFO("prism of " << n << "-gons");
    check_probes(w);
    CHECK(static_cast<int>(w.probes().size()) > GaussMapWalk::kMinProbes);
  }
  // every vertex of a small shape is a probe, a flat polygon included
  for (const auto& s : {shapes::cube<double>(1.0), shapes::prism<double>(5, 1.0, 1.0),
                        shapes::regular_polygon<double>(3, 1.0), shapes::regular_polygon<double>(40, 1.0)}) {
    const GaussMapWalk w(s);
    check_probes(w);
  }
}

TEST_CASE("probes depend on the combinatorics only: the same for every pose and number type",
          "[walk][probes]") {
  std::mt19937_64 rng(11);
  for (int it = 0; it < 5; ++it) {
    const auto hull = test::sphere_hull(rng, 48);
    const auto moved = test::moved(hull, test::random_rotation(rng), test::V3(3.0, -1.0, 0.5));
    const auto as_float = ConvexPolyhedron<float>::convert_from(moved);
    const GaussMapWalk w(hull), wm(moved), wf(as_float);
    CHECK(wm.probes() == w.probes());
    CHECK(wf.probes() == w.probes());
  }
}

TEST_CASE("face chunks: the BFS order in chunks of at most kFaceChunk, no face with its parent",
          "[walk][chunks]") {
  std::mt19937_64 rng(23);
  std::vector<ConvexPolyhedron<double>> shapes_list = {shapes::cube<double>(1.0),
                                                       shapes::prism<double>(40, 1.0, 0.5),
                                                       shapes::regular_polygon<double>(5, 1.0)};
  for (int n : {8, 40, 150, 400}) shapes_list.push_back(test::large_sphere_hull(rng, n));
  for (const auto& p : shapes_list) {
    const GaussMapWalk w(p);
    const auto& order = w.face_order();
    const auto& parent = w.face_parent();
    const auto& ch = w.face_chunks();
    const int nf = p.face_count();
    INFO("faces " << nf);
    REQUIRE(ch.size() >= 2);
    CHECK(ch.front() == 0);
    CHECK(ch.back() == nf);
    std::vector<int> chunk_of(static_cast<std::size_t>(nf), -1);  // by face
    for (std::size_t c = 0; c + 1 < ch.size(); ++c) {
      CHECK(ch[c] < ch[c + 1]);
      CHECK(ch[c + 1] - ch[c] <= GaussMapWalk::kFaceChunk);
      for (int i = ch[c]; i < ch[c + 1]; ++i)
        chunk_of[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])] = static_cast<int>(c);
    }
    for (int i = 1; i < nf; ++i) {
      const int f = order[static_cast<std::size_t>(i)], pf = parent[static_cast<std::size_t>(i)];
      INFO("position " << i);
      REQUIRE(pf >= 0);
      CHECK(chunk_of[static_cast<std::size_t>(pf)] < chunk_of[static_cast<std::size_t>(f)]);
    }
  }
  // Large hulls have long chunks (the traversal's chunked seed pass needs a
  // mean of sat::kTraversalMinMeanChunk): 400 points, ~796 faces.
  const GaussMapWalk big(shapes_list.back());
  CHECK(big.face_count() >= sat::kTraversalMinMeanChunk * (static_cast<int>(big.face_chunks().size()) - 1));
}
