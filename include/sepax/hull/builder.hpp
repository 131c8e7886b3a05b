// sepax/hull/builder.hpp
//
// The state one hull build shares between its steps, and the steps' names; each step is defined in the
// header of its phase:
//   welded_points.hpp  input checks, tolerances, welding
//   quickhull.hpp      initial simplex, conflict lists, visible region, horizon, cone, re-assignment
//   flat_hull.hpp      a point set within the flat tolerance of a plane: its 2D hull as a double-sided face
//   face_merge.hpp     coplanar triangles into faces (union-find; after a local removal only around it),
//                      zero-area triangles, fold splits
//   face_loops.hpp     each face's boundary loop, vertices in the middle of an edge, strictly convex corners
//   precheck.hpp       float: what ConvexPolyhedron validation will check, with half its tolerances
//   repair.hpp         float: points left outside are pinned and the hull rebuilt; the fallback policy
//   fallbacks.hpp      float: simplex_hull, thin_plane, projected_slab, tent_hull
// The float-versus-exact decisions are those of HullTraits<T> (traits.hpp), a friend of the builder.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "../convex_polyhedron.hpp"
#include "../error.hpp"
#include "../number_traits.hpp"
#include "../vec3.hpp"
#include "hull_distance.hpp"
#include "index.hpp"
#include "plane_tree.hpp"
#include "to_polyhedron.hpp"
#include "traits.hpp"

namespace sepax::hull::detail {

/// A quickhull triangle: welded point indices counter-clockwise from outside, its neighbours and its points.
template <Number T>
struct Triangle {
  std::array<int, 3> v{};   ///< welded point indices, counter-clockwise from outside
  std::array<int, 3> nb{};  ///< triangle across edge v[i] -> v[i+1]
  Plane<T> pl;              ///< (exact T with double points: computed by Builder::plane() when needed)
  bool has_plane = true;
  bool alive = true;
  std::vector<int> conflict;  ///< points outside this face, waiting to be added
  /// float T: points above this face by at most eps (on it within the tolerance).  They are not outside,
  /// but they are not inside either: when the face is replaced they are tested against the new faces again.
  std::vector<int> on;

  Triangle() = default;
  Triangle(const Triangle&) = default;
  Triangle& operator=(const Triangle&) = default;
  /// Moves say noexcept although T's may not (gmpxx's moved-from mpq_class allocates anew, and GMP aborts
  /// rather than throws when it cannot): the builder's vector of triangles then grows by moving each
  /// triangle, not by copying its plane and point lists.
  Triangle(Triangle&&) noexcept = default;
  Triangle& operator=(Triangle&&) noexcept = default;
};

/// Float T: a face group's area-weighted plane (HullTraits<T>::kRefits).
template <Number T>
struct GroupFit {
  Vec3<T> area = Vec3<T>(T(0), T(0), T(0));      ///< sum of triangle cross products
  Plane<T> pl{Vec3<T>(T(0), T(0), T(0)), T(0)};  ///< the refitted plane (HullTraits::group_plane)
  Vec3<double> sum = Vec3<double>(0, 0, 0);      ///< sum of the group's vertices (local coordinates)
};
/// Exact T: no fitted plane to keep (a group's plane is its plane triangle's), so a group holds no T value.
struct NoGroupFit {};

/// A union-find group of triangles becoming one output face.
template <Number T>
struct FaceGroup {
  std::vector<int> verts;  ///< sorted welded point indices
  /// float: the area-weighted plane; exact: nothing
  [[no_unique_address]] std::conditional_t<HullTraits<T>::kRefits, GroupFit<T>, NoGroupFit> fit;
  int plane_tri = -1;       ///< exact: the triangle whose plane is the group's
  bool degenerate = false;  ///< a single zero-area triangle
  std::vector<int> splits;  ///< sorted ids of the split faces its triangles came from

  FaceGroup() = default;
  FaceGroup(const FaceGroup&) = default;
  FaceGroup& operator=(const FaceGroup&) = default;
  /// noexcept as Triangle's moves (the vector of groups grows by moving).
  FaceGroup(FaceGroup&&) noexcept = default;
  FaceGroup& operator=(FaceGroup&&) noexcept = default;
};

/// The sweep's record of a point it kept after searching the faces around its own (first_above_nearby).
template <Number T>
struct SweepMemo {
  int face = -1;          ///< the face the point was kept on (-1: no record)
  T limit = T(0);         ///< the threshold it was tested with
  std::size_t start = 0;  ///< the faces the search reached: Builder::sweep_faces_[start, start + size)
  std::size_t size = 0;   ///< (every face tested, and every neighbour of a face passed through)
};

/// Live triangles from which the clean-up's rejected vertices are taken out of the triangles
/// (Builder::remove_vertices, vertex_removal.hpp) rather than the hull built again from the start
/// (measured, docs/hull.md: from a few hundred triangles on the removal costs less than a second build).
inline constexpr std::size_t kLocalRemovalFaces = 256;

/// An edge slot's pair of groups (roots) found apart, with the versions they had then (Builder::plane_merges).
struct ApartPair {
  int x = -1, y = -1, vx = 0, vy = 0;
};

/// Float T: the plane merges of the last face stage (Builder::merge_and_build), from which the next face stage
/// on the same triangles, after a local removal and quickhull (remove_vertices), merges again only around
/// the triangles that changed (Builder::merge_locally).
template <Number T>
struct MergeRecord {
  bool valid = false;                              ///< (reset when the triangles start over: solid)
  std::vector<int> root;                           ///< per triangle: its group's root (-1: dead)
  std::vector<std::array<int, 6>> tri;             ///< per triangle: its vertices and its neighbours
  std::vector<std::pair<int, FaceGroup<T>>> kept;  ///< roots united after the record, as recorded
  bool recorded = false;                           ///< the stage is past its plane merges: unite keeps
};

/// Whether float face stages after a local removal merge only around what changed (merge_locally); false
/// makes every face stage merge all the triangles, which must give the same faces (the hull tests compare).
/// (An atomic, read once per face stage: a test may switch it while other threads build hulls.)
inline std::atomic<bool> local_face_merges{true};
/// Whether the sweep's search for a kept point first walks towards it and then passes only through the
/// triangles near it (first_above_nearby); false makes it pass through every face within reach of the
/// point's height, a larger search whose builds take other (equally valid) turns: a test reproducing a
/// build's path switches it off.  (An atomic, read once per sweep.)
inline std::atomic<bool> sweep_walks{true};
/// The float face stages that merged only around what changed (merge_locally), for the tests to see.
inline std::atomic<std::size_t> local_face_stages{0};
/// The results of passes that went on from their own triangles that validation refused (Builder::finish),
/// each followed by a build from the start, for the tests to see.
inline std::atomic<std::size_t> local_surface_refusals{0};

/// Float T: the best results of the repair passes (repair.hpp).
template <Number T>
struct RepairLog {
  std::optional<ConvexPolyhedron<T>> nearest;  ///< nearest every point (height or distance, the larger)
  /// lowest heights above the face planes; empty while that result is the nearest one (lowest_is_nearest),
  /// which is then not copied (the hull of 10^5 points takes tens of megabytes)
  std::optional<ConvexPolyhedron<T>> lowest;
  bool lowest_is_nearest = false;
  double nearest_out = 0, nearest_height = 0, lowest_height = 0;  ///< x eps

  /// Whether a pass has been measured for the lowest heights.
  bool has_lowest() const { return lowest_is_nearest || lowest.has_value(); }
  /// The result with the lowest heights.
  std::optional<ConvexPolyhedron<T>>& lowest_result() { return lowest_is_nearest ? nearest : lowest; }
  /// Replaces the nearest result (out and height x eps), keeping the lowest one.
  void set_nearest(ConvexPolyhedron<T> h, double out, double height) {
    if (lowest_is_nearest) {
      lowest = std::move(nearest);
      lowest_is_nearest = false;
    }
    nearest = std::move(h);
    nearest_out = out;
    nearest_height = height;
  }
};

/// What Builder::tris_ holds.
enum class TrisState {
  none,          ///< nothing to go on from (no build yet, a flat build, or a removal that failed)
  solid_build,   ///< the last solid build's quickhull triangulation (its clean-up may have rejected points)
  solid_result,  ///< float: that triangulation is the last pass's solid result's, every conflict list empty
};

/// The hull algorithm of convex_hull (convex_hull.hpp); allow_tent is false for a tent's own build.
template <Number T>
ConvexPolyhedron<T> build_hull(std::span<const Vec3<T>> points, bool allow_tent);

/// One hull build: the welded points, the quickhull triangles, the face groups and, for float T, the
/// repair state, shared by the steps (each defined in its phase's header, listed above).
template <Number T>
class Builder {
 public:
  Builder(std::span<const Vec3<T>> input, bool allow_tent) : in_(input), tent_(allow_tent) {}

  // The steps build_hull calls, in order.
  void check_input();
  void weld();
  std::optional<ConvexPolyhedron<T>> build_pass(bool may_fail, const std::vector<int>& pinned = {});
  std::uint64_t measure(ConvexPolyhedron<T> result, std::vector<int>& outside, RepairLog<T>& log);
  void pin(const std::vector<int>& outside);
  bool repeats(std::uint64_t digest, std::uint64_t last_digest, const std::vector<int>& outside) const;
  std::uint64_t removed_hash() const;
  static std::uint64_t digest(const ConvexPolyhedron<T>& h);
  ConvexPolyhedron<T> choose_result(RepairLog<T>& log);

 private:
  using Traits = HullTraits<T>;
  friend Traits;
  using Tri = Triangle<T>;
  using Group = FaceGroup<T>;

  // ---- repair.hpp ----
  std::optional<ConvexPolyhedron<T>> resume(const std::vector<int>& pinned, std::vector<int>& reject);
  void try_simplex(RepairLog<T>& log);
  std::optional<ConvexPolyhedron<T>> try_projected_slab(const RepairLog<T>& log);
  std::optional<ConvexPolyhedron<T>> try_tent(const ConvexPolyhedron<T>& chosen);
  double outside_points(const ConvexPolyhedron<T>& h, std::vector<int>& outside, double& height) const;
  std::vector<int> measure_order(bool coherent) const;
  // ---- fallbacks.hpp ----
  std::optional<ConvexPolyhedron<T>> tent_hull(const ConvexPolyhedron<T>& h, Vec3<double>& nrm);
  std::optional<ConvexPolyhedron<T>> simplex_hull();
  bool thin_plane(const ConvexPolyhedron<T>& h, Vec3<double>& nrm, double& lo, double& hi) const;
  std::vector<int> extreme_points() const;
  double shadow_out(const ConvexPolyhedron<T>& h, const Vec3<double>& nrm) const;
  std::optional<ConvexPolyhedron<T>> projected_slab(const Vec3<double>& nrm, double lo, double hi);
  // ---- welded_points.hpp ----
  void add_point(int input_index, const Vec3<T>& loc);
  // ---- quickhull.hpp ----
  const Plane<T>& plane(int f);
  static T length(const Vec3<T>& v) { return Traits::length(v); }
  std::optional<ConvexPolyhedron<T>> build(const std::vector<int>& active, std::vector<int>& reject);
  int new_tri(int p0, int p1, int p2);
  void assign(int p, int first);
  template <class Faces>
  void assign_among(int p, const Faces& faces);
  template <class Faces, class Limit>
  bool conflict_among(int p, const Faces& faces, const Limit& limit, typename Traits::NearFace& near);
  void drop_dead_live_faces();
  void index_live_faces(std::size_t points);
  void assign_live(int p);
  T threshold(int p) const;
  bool sweep();
  int first_above_nearby(int p, int f, T reach, bool walk, std::vector<int>& seen,
                         std::vector<int>& queue) const;
  static int edge_index(const Tri& t, int from);
  std::optional<ConvexPolyhedron<T>> solid(const std::vector<int>& active, int a, int b, int c, int d,
                                           std::vector<int>& reject);
  std::optional<ConvexPolyhedron<T>> quickhull_and_faces(std::vector<int>& reject);
  void expand();
  bool remove_vertices(const std::vector<int>& reject);
  bool remove_vertex(int v, int from);
  // ---- flat_hull.hpp ----
  std::optional<ConvexPolyhedron<T>> polygon(const std::vector<int>& active, const Vec3<T>& n,
                                             std::vector<int>& reject);
  // ---- face_merge.hpp ----
  static bool split_apart(const Group& a, const Group& b);
  T tri_area2(const Tri& t) const;
  int find(int x);
  void unite(int x, int y);
  std::optional<ConvexPolyhedron<T>> merge_and_build(std::vector<int>& reject);
  void init_group(int f);
  void plane_merges(const std::vector<int>& tris, const std::vector<char>* among,
                    std::vector<ApartPair>& apart);
  bool merge_locally(const std::vector<int>& live);
  void record_merges(const std::vector<int>& live, bool valid);
  bool strands_vertex(int x, int y);
  std::vector<int> fold_choice(const std::vector<int>& live, const std::map<int, std::vector<int>>& folds);
  bool split_groups(const std::vector<int>& live, std::vector<int> ids);
  double segment_distance(int v, int a, int b) const;
  // ---- face_loops.hpp ----
  std::optional<ConvexPolyhedron<T>> extract(const std::vector<int>& live, std::vector<int>& reject);
  // ---- precheck.hpp ----
  void start_at_best_apex(std::vector<int>& l) const;
  int least_significant(const std::vector<int>& l) const;
  void prevalidate(std::vector<std::vector<int>>& loops, std::vector<int>& reject, bool flat = false,
                   std::vector<std::pair<int, int>>* merges = nullptr,
                   const std::vector<int>* loop_group = nullptr, std::vector<int>* split = nullptr,
                   ScannedPlanes<T>* scanned = nullptr);

  /// Welded point i in local coordinates (Traits::kLocalIsInput: the input point itself).
  const Vec3<T>& local_point(int i) const {
    if constexpr (Traits::kLocalIsInput) {
      return input_point(i);
    } else {
      return q_[as_index(i)];
    }
  }
  /// The number of welded points.
  std::size_t welded_count() const { return pts_.size(); }
  /// The input point welded point v comes from.
  const Vec3<T>& input_point(int v) const { return in_[as_index(pts_[as_index(v)])]; }
  T height(const Plane<T>& pl, int p) const { return T(dot(pl.normal, local_point(p)) - pl.offset); }

  /// The output polyhedron, validated.  A validation failure is a builder bug (std::logic_error), except
  /// on triangles a pass went on from (local_surface_: the clean-up's vertices taken out of them, or a
  /// repair pass's pinned points added to the last pass's): there it gives none with local_surface_failed_
  /// set, and the pass builds from the start (build_pass, resume).
  template <class F>
  std::optional<ConvexPolyhedron<T>> finish(F&& make) {
    try {
      return make();
    } catch (const InvalidInput& e) {
      if (local_surface_) {
        local_surface_failed_ = true;
        local_surface_refusals.fetch_add(1, std::memory_order_relaxed);
        return std::nullopt;
      }
      throw std::logic_error(std::string("convex_hull: the hull failed validation (a bug): ") + e.what());
    }
  }
  /// quickhull_and_faces on triangles a pass went on from (finish); none with reject empty and
  /// local_surface_failed_ set when validation refuses the result.
  std::optional<ConvexPolyhedron<T>> faces_of_local_surface(std::vector<int>& reject) {
    local_surface_ = true;
    local_surface_failed_ = false;
    struct Reset {
      bool& flag;
      ~Reset() { flag = false; }
    } reset{local_surface_};
    auto result = quickhull_and_faces(reject);
    if (local_surface_failed_) reject.clear();
    return result;
  }

  std::span<const Vec3<T>> in_;
  double extent_ = 0;
  Vec3<T> centre_;
  T eps_, flat_, weld_;
  std::vector<int> pts_;    // welded point -> input index
  std::vector<Vec3<T>> q_;  // welded point, local coordinates (empty where Traits::kLocalIsInput)
  std::vector<Tri> tris_;
  std::vector<int> parent_;
  std::vector<int> active_;                     // the points of the current build
  std::array<int, 4> simplex_{-1, -1, -1, -1};  // the first build's initial simplex
  Vec3<T> base_normal_;                         // normal of its initial triangle
  std::vector<Group> groups_;
  std::vector<int> group_version_;    // per group root: the unions it has taken (face_merge.hpp)
  MergeRecord<T> merge_record_;       // float: the last face stage's plane merges (face_merge.hpp)
  std::vector<char> removed_;         // points the clean-up rejected (put back when pinned)
  std::uint64_t removed_at_pin_ = 0;  // removed_hash() when pin() was last called (the last pass's end)
  std::vector<char> pinned_;          // float: points a repair pass put back
  bool any_pinned_ = false;
  TrisState tris_state_ = TrisState::none;  ///< what tris_ holds: remove_vertices and resume go on from it
  bool local_surface_ = false;          // finishing triangles a pass went on from (faces_of_local_surface)
  bool local_surface_failed_ = false;   // and validation refused their result
  bool local_removal_refused_ = false;  // a local removal's result was refused: every later one starts over
  std::vector<char> out_vertex_;        // vertices of the last output
  std::vector<std::vector<int>> star_;  // float: vertex -> live triangles around it
  std::vector<std::vector<int>> loop_pool_;  // face loops' storage between extractions (face_loops.hpp)
  std::vector<std::vector<int>> list_pool_;  // dead triangles' point lists, storage for new ones (quickhull)
  std::vector<int> next_vertex_;             // scratch, per welded point (-1: none)
  std::vector<int> gone_;                    // scratch, per eye
  std::vector<int> live_faces_;   // live triangles in index order, among tris_[0, live_made_) (and some dead)
  std::size_t live_made_ = 0;     // (updated at each eye whose visible region was forced)
  std::size_t live_dead_ = 0;     // >= the faces of live_faces_ dead since drop_dead_live_faces
  std::vector<Vec3<double>> qd_;  // exact T: q_ as doubles, when shadow_
  bool shadow_ = false;           // exact T: every welded coordinate is exactly a double
  std::vector<std::array<int, 3>> horizon_;           // scratch, per eye
  static constexpr std::size_t kHorizonPool = 16384;  ///< bytes: a horizon of ~200 edges without allocation
  std::vector<std::byte> horizon_pool_ = std::vector<std::byte>(kHorizonPool);  // the horizon map's storage
  std::vector<int> moved_;       // scratch, per eye: the points of a removed face
  std::vector<int> degree_;      // scratch, per welded point
  std::vector<int> union_;       // scratch: a union of two face groups' vertices (unite)
  std::vector<int> shared_;      // scratch: the vertices two face groups share (unite)
  std::vector<int> added_;       // scratch: the smaller group's vertices the larger lacks (unite)
  std::vector<int> eye_visits_;  // times each welded point was the eye (kHullMaxEyeVisits)
  std::vector<int> nomerge_;     // triangle -> id of the face it was split from (0: none)
  int splits_ = 0;
  bool tent_;  // float: may try tent_hull (not in a tent's own build)
  /// Float T: the planes of live_faces_ as they were at one forced eye (assign_live), tree item k being
  /// face live_tree_faces_[k]; the faces made since, tris_[live_tree_end_, ...), are passed over in order.
  std::optional<std::conditional_t<Traits::kRechecksRounding, PlaneTree<T>, char>> live_tree_;
  std::vector<int> live_tree_faces_;
  std::size_t live_tree_end_ = 0;
  /// Float T: face tests the forced steps' re-assignments made (or are about to make) past live_tree_
  /// since it was built, points x faces (index_live_faces).
  double live_scan_debt_ = 0;
  /// Per welded point: what the last sweep's search found for it when it kept it (SweepMemo::face -1
  /// otherwise); the next sweep keeps it without a search while every face reached is still alive.
  std::vector<SweepMemo<T>> sweep_memo_;
  std::vector<int> sweep_faces_;  ///< the faces each record of sweep_memo_ reached, one after another
};

}  // namespace sepax::hull::detail
