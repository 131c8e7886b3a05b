// sepax/gauss_map_walk.hpp
//
// GaussMapWalk: the per-hull data the traversal SAT (sat_traversal.hpp) walks
// on, precomputed once per hull.  It depends only on the combinatorics of the
// polyhedron (never on coordinates or on T), so one GaussMapWalk serves every
// pose of a hull and its exact image (convert_from()).  Contents (structure of
// arrays, all int; each described on its member):
//   * vertex adjacency in CSR form (the fan the hill climbs and the arc walk
//     scan);
//   * half-edge origin / face / next / prev (the face loops);
//   * a breadth-first order of the faces over face adjacency with each face's
//     parent, cut into chunks that hold no face with its parent;
//   * probe_count(V) probe vertices spread over the vertex graph, which prune
//     a face of the other shape without a climb.
#pragma once

#include <vector>

#include "convex_polyhedron.hpp"
#include "error.hpp"

namespace sepax {

/// The traversal's walk data of one hull:
///   * vertex adjacency in CSR form: for vertex v, entries
///     [adj_begin(v), adj_end(v)) hold one outgoing half-edge h of v each, the
///     neighbour origin(h ^ 1) and the undirected edge h >> 1 -- the fan the
///     hill climbs and the arc walk scan;
///   * half-edge origin / face / next / prev (the face loops, for walking the
///     vertices of one face);
///   * a breadth-first order of the faces over face adjacency, with each face's
///     parent in that tree (-1 for the root): the traversal computes a face's
///     support vertex by hill-climbing from its parent's support vertex;
///     that order cut into chunks that hold no face with its parent;
///   * probe_count(V) probe vertices spread over the vertex graph (farthest
///     point sampling by edge hops): before the traversal climbs for a face of
///     the other shape, it looks for a probe below the best candidate so far,
///     which prunes the face without a climb (sat_traversal.hpp, step 1).
///     They are chosen from the graph alone, so they too are the same for
///     every pose and number type.
class GaussMapWalk {
 public:
  GaussMapWalk() = default;

  template <Number T>
  explicit GaussMapWalk(const ConvexPolyhedron<T>& p) {
    nv_ = p.vertex_count();
    ne_ = p.edge_count();
    nf_ = p.face_count();
    flat_ = p.is_flat();
    const auto& hes = p.half_edges();
    const auto nh = hes.size();
    origin_.resize(nh);
    face_.resize(nh);
    next_.resize(nh);
    prev_.resize(nh);
    for (std::size_t h = 0; h < nh; ++h) {
      origin_[h] = hes[h].origin;
      face_[h] = hes[h].face;
      next_[h] = hes[h].next;
      prev_[h] = hes[h].prev;
    }
    adj_start_.assign(static_cast<std::size_t>(nv_) + 1, 0);
    adj_half_.clear();
    adj_vertex_.clear();
    adj_edge_.clear();
    for (int v = 0; v < nv_; ++v) {
      for (int h : p.vertex_half_edges(v)) {
        adj_half_.push_back(h);
        adj_vertex_.push_back(hes[static_cast<std::size_t>(h ^ 1)].origin);
        adj_edge_.push_back(h >> 1);
      }
      adj_start_[static_cast<std::size_t>(v) + 1] = static_cast<int>(adj_half_.size());
    }
    // BFS over faces (faces adjacent across an edge).
    face_order_.clear();
    face_parent_.clear();
    std::vector<int> parent(static_cast<std::size_t>(nf_), -2);
    if (nf_ > 0) {
      parent[0] = -1;
      face_order_.push_back(0);
      for (std::size_t i = 0; i < face_order_.size(); ++i) {
        const int f = face_order_[i];
        const int first = p.face(f).edge;
        int h = first;
        do {
          const int g = face_[static_cast<std::size_t>(h ^ 1)];
          if (parent[static_cast<std::size_t>(g)] == -2) {
            parent[static_cast<std::size_t>(g)] = f;
            face_order_.push_back(g);
          }
          h = next_[static_cast<std::size_t>(h)];
        } while (h != first);
      }
    }
    for (int f : face_order_) face_parent_.push_back(parent[static_cast<std::size_t>(f)]);
    choose_face_chunks();
    choose_probes();
    triangulated_ = true;
    for (std::size_t h = 0; h < nh; ++h) {
      if (next_[static_cast<std::size_t>(next_[static_cast<std::size_t>(next_[h])])] != static_cast<int>(h))
        triangulated_ = false;
    }
  }

  int vertex_count() const { return nv_; }
  int edge_count() const { return ne_; }
  int face_count() const { return nf_; }
  bool is_flat() const { return flat_; }
  /// Every face is a triangle (the hill climb then needs no far-vertex pass).
  bool triangulated() const { return triangulated_; }

  /// True when this data was built for p's combinatorics (checked by counts:
  /// build the walk data from the hull itself or a with_vertices/convert_from
  /// copy of it).
  template <Number T>
  bool fits(const ConvexPolyhedron<T>& p) const {
    return p.vertex_count() == nv_ && p.edge_count() == ne_ && p.face_count() == nf_ && p.is_flat() == flat_;
  }

  /// Throws InvalidInput (BadIndex) when the data does not fit p.
  template <Number T>
  void check_fits(const ConvexPolyhedron<T>& p, const char* which) const {
    if (!fits(p)) {
      throw InvalidInput(ErrorCode::BadIndex,
                         std::string("traversal: the GaussMapWalk passed for shape ") + which +
                             " was built for a different polyhedron (V/E/F " + std::to_string(nv_) + "/" +
                             std::to_string(ne_) + "/" + std::to_string(nf_) + ", shape has " +
                             std::to_string(p.vertex_count()) + "/" + std::to_string(p.edge_count()) + "/" +
                             std::to_string(p.face_count()) + ")");
    }
  }

  // ---- vertex adjacency (CSR) ----
  int adj_begin(int v) const { return adj_start_[static_cast<std::size_t>(v)]; }
  int adj_end(int v) const { return adj_start_[static_cast<std::size_t>(v) + 1]; }
  int adj_half_edge(int i) const { return adj_half_[static_cast<std::size_t>(i)]; }
  int adj_vertex(int i) const { return adj_vertex_[static_cast<std::size_t>(i)]; }
  int adj_edge(int i) const { return adj_edge_[static_cast<std::size_t>(i)]; }

  // ---- half-edges ----
  int origin(int h) const { return origin_[static_cast<std::size_t>(h)]; }
  int face(int h) const { return face_[static_cast<std::size_t>(h)]; }
  int next(int h) const { return next_[static_cast<std::size_t>(h)]; }
  int prev(int h) const { return prev_[static_cast<std::size_t>(h)]; }
  int edge_tail(int e) const { return origin_[static_cast<std::size_t>(2 * e)]; }
  int edge_head(int e) const { return origin_[static_cast<std::size_t>(2 * e + 1)]; }
  int edge_face(int e, int side) const { return face_[static_cast<std::size_t>(2 * e + side)]; }
  /// edge_face(e, side) == edge_faces()[2 e + side], for loops over every edge.
  const int* edge_faces() const { return face_.data(); }

  /// The number of probe vertices lies in [kMinProbes, kMaxProbes] (both
  /// multiples of the 4 float lanes), or is every vertex of a smaller shape.
  static constexpr int kMinProbes = 16;
  static constexpr int kMaxProbes = 28;
  /// Probes of a shape with nv vertices: nv / 8 within [kMinProbes,
  /// kMaxProbes], at most nv.  A hull of N points spread over a sphere keeps
  /// about the same share of its vertices as probes, so the deepest probe
  /// stays about as deep relative to the face spacing as N grows (measured:
  /// 16 probes at N = 256 left ~105 faces per query whose seed and deepest
  /// probe both failed; 28 probes are 6-7% faster there, while 24 instead of
  /// 16 at N = 32 were 10% slower, docs/traversal.md "Why it is built this way").
  static constexpr int probe_count(int nv) {
    const int k = nv / 8 < kMinProbes ? kMinProbes : nv / 8 > kMaxProbes ? kMaxProbes : nv / 8;
    return k < nv ? k : nv;
  }
  /// The probe vertices, in the order they were chosen: vertex 0, then each
  /// time the vertex furthest (in edge hops) from those already chosen, the
  /// lowest index among equally far ones; probe_count(vertex count) of them.
  const std::vector<int>& probes() const { return probes_; }

  // ---- faces in breadth-first order ----
  const std::vector<int>& face_order() const { return face_order_; }
  /// Parent (in the BFS tree) of face_order()[i]; -1 for the root.
  const std::vector<int>& face_parent() const { return face_parent_; }
  /// The BFS order cut into chunks of at most kFaceChunk positions, none of
  /// which holds a face together with its parent: chunk c is positions
  /// [face_chunks()[c], face_chunks()[c + 1]), the last entry is the face
  /// count.  The traversal takes the seed test of a whole chunk before any of
  /// its faces climbs (no face's seed can change inside its chunk).
  const std::vector<int>& face_chunks() const { return face_chunks_; }
  static constexpr int kFaceChunk = 64;

 private:
  int nv_ = 0, ne_ = 0, nf_ = 0;
  bool flat_ = false;
  bool triangulated_ = false;
  std::vector<int> adj_start_, adj_half_, adj_vertex_, adj_edge_;
  std::vector<int> origin_, face_, next_, prev_;
  std::vector<int> face_order_, face_parent_, face_chunks_;
  std::vector<int> probes_;

  // Greedy: a chunk ends before the first position whose parent lies in it,
  // or after kFaceChunk positions.
  void choose_face_chunks() {
    face_chunks_.clear();
    const int n = static_cast<int>(face_order_.size());
    std::vector<int> pos(static_cast<std::size_t>(nf_), -1);
    for (int i = 0; i < n; ++i) pos[static_cast<std::size_t>(face_order_[static_cast<std::size_t>(i)])] = i;
    int start = 0;
    if (n > 0) face_chunks_.push_back(0);
    for (int i = 1; i < n; ++i) {
      const int pp = pos[static_cast<std::size_t>(face_parent_[static_cast<std::size_t>(i)])];
      if (pp >= start || i - start == kFaceChunk) {
        start = i;
        face_chunks_.push_back(i);
      }
    }
    face_chunks_.push_back(n);
  }

  // Farthest point sampling on the vertex graph (BFS distances, O(kMaxProbes
  // (V + E))): on a hull of points spread over a sphere the probes end up
  // spread over it, so for most directions one of them lies deep.
  void choose_probes() {
    probes_.clear();
    if (nv_ == 0) return;
    std::vector<int> dist(static_cast<std::size_t>(nv_), nv_ + 1), queue;
    queue.reserve(static_cast<std::size_t>(nv_));
    int next = 0;
    const int want = probe_count(nv_);
    while (static_cast<int>(probes_.size()) < want) {
      probes_.push_back(next);
      // hop distances to the chosen set, updated from the new probe
      queue.assign(1, next);
      dist[static_cast<std::size_t>(next)] = 0;
      for (std::size_t i = 0; i < queue.size(); ++i) {
        const int v = queue[i];
        const int dv = dist[static_cast<std::size_t>(v)];
        for (int j = adj_begin(v); j < adj_end(v); ++j) {
          const int u = adj_vertex(j);
          if (dist[static_cast<std::size_t>(u)] > dv + 1) {
            dist[static_cast<std::size_t>(u)] = dv + 1;
            queue.push_back(u);
          }
        }
      }
      int far = -1;
      for (int v = 0; v < nv_; ++v) {
        if (dist[static_cast<std::size_t>(v)] > (far < 0 ? 0 : dist[static_cast<std::size_t>(far)])) far = v;
      }
      if (far < 0) break;  // every vertex is a probe
      next = far;
    }
  }
};

}  // namespace sepax
