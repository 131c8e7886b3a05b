// sepax/hull/traits.hpp
//
// The number-type-dependent decisions of the hull builder, one traits type per kind of number type (the
// model: CGAL's Convex_hull_traits_3), selected through number_traits<T>::is_exact.  The steps call them
// as Traits::decision(builder, ...):
//   scale, local_points           tolerances and frame; the points welding works on
//   shadow, weld                  exact: the double copy of the points; welding
//   classify, NearFace            "is p outside face f" (float: by more than eps; near points kept)
//   outside_limit                 how far above a face p must be (float: eps, 0 once pinned)
//   farthest, sees, zero_area     the eye of a face; "does the eye see face f"; "has f zero area"
//   set_plane                     a new triangle's plane (exact with double points: only when needed)
//   coplanar, certainly_apart     "are two face groups one face" (exact: filtered for double points)
//   init_group_fit, group_plane    a face group's plane (exact: its triangle's, built only when needed)
//   refit, add_area, unite_sum, adopt_plane  float: a group's area-weighted plane
//   collinear, left_turn, convex_corner  the tolerant (float) or exact turn tests
//   rounding_case                 a case only rounding causes: for exact T a builder bug
// and the capabilities kRepairs, kRechecksRounding, kPrechecks, kTriangleFacesConvex, kWorkingScale,
// kTolerantChain, kRefits.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "../convex_polyhedron.hpp"
#include "../error.hpp"
#include "../number_traits.hpp"
#include "../orientation_filter.hpp"
#include "../tolerances.hpp"
#include "../vec3.hpp"
#include "index.hpp"
#include "orientation_filter.hpp"

namespace sepax::hull::detail {

/// Exact T: every decision exact, tolerances zero.  When every welded coordinate is exactly a double, the
/// predicates are decided by orientation_filter first, in T only when it cannot decide.
template <Number T>
struct ExactHullTraits {
  /// The exact hull holds every point: no repair passes, no fallbacks.
  static constexpr bool kRepairs = false;
  /// Decisions are exact: nothing kept near a face is tested again.
  static constexpr bool kRechecksRounding = false;
  /// Validation is exact too: no pre-check of what it will see.
  static constexpr bool kPrechecks = false;
  /// A face that is one triangle with area turns left at every corner (by |normal|^2).
  static constexpr bool kTriangleFacesConvex = true;
  /// No exponent range to stay within: built at the input's scale.
  static constexpr bool kWorkingScale = false;
  /// The flat hull is the strict chain: no corner is dropped within a tolerance.
  static constexpr bool kTolerantChain = false;
  /// A welded point is the input point itself (Builder::local_point reads the input; nothing is copied).
  static constexpr bool kLocalIsInput = true;
  /// A face group's plane is its plane triangle's: groups keep no fitted plane (FaceGroup::fit).
  static constexpr bool kRefits = false;
  /// Suffixes of the error messages naming the tolerance.
  static constexpr const char* kWeldNote = "";
  static constexpr const char* kFlatNote = "";
  static constexpr const char* kLineNote = "";

  /// Tolerances zero, no change of frame.
  template <class B>
  static void scale(B& b, const Vec3<T>&, const Vec3<T>&) {
    b.centre_ = Vec3<T>(T(0), T(0), T(0));
    b.eps_ = b.flat_ = b.weld_ = T(0);
  }
  /// The points welding works on: the input as given (no copy).
  template <class B>
  static std::span<const Vec3<T>> local_points(const B& b) {
    return b.in_;
  }

  /// Exact duplicates are one point (loc sorted lexicographically by order).
  template <class B>
  static void weld(B& b, std::span<const Vec3<T>> loc, const std::vector<int>& order) {
    for (std::size_t k = 0; k < order.size(); ++k) {
      if (k > 0 && loc[as_index(order[k])] == loc[as_index(order[k - 1])]) continue;
      b.add_point(order[k], loc[as_index(order[k])]);
    }
  }

  /// The points as doubles (qd_, one per point of loc; Builder::weld keeps the welded points'), used when
  /// every coordinate is exactly a double (checked exactly): welding then sorts on them, and the quickhull
  /// predicates are decided by orientation_filter, in T only when it cannot decide.
  template <class B>
  static void shadow(B& b, std::span<const Vec3<T>> loc) {
    b.shadow_ = true;
    b.qd_.resize(loc.size());
    for (std::size_t i = 0; i < loc.size() && b.shadow_; ++i)
      for (int c = 0; c < 3 && b.shadow_; ++c) {
        b.qd_[i][c] = to_double(loc[i][c]);
        b.shadow_ = std::isfinite(b.qd_[i][c]) && from_double<T>(b.qd_[i][c]) == loc[i][c];
      }
    if (!b.shadow_) b.qd_.clear();
  }

  /// Not used for exact T (no square roots).
  static T length(const Vec3<T>&) { return T(0); }

  /// The sign of p's height above triangle f's plane (the sign of det[v1 - v0, v2 - v0, p - v0]), and in
  /// approx an estimate of the determinant for choosing among points (not for deciding).
  template <class B>
  static int side(B& b, int f, int p, double& approx) {
    const auto& t = b.tris_[as_index(f)];
    if (b.shadow_) {
      const FilteredSign r = orientation_filter(b.qd_[as_index(t.v[0])], b.qd_[as_index(t.v[1])],
                                                b.qd_[as_index(t.v[2])], b.qd_[as_index(p)]);
      approx = r.det;
      if (r.certain) return r.det > 0 ? 1 : -1;
    }
    const T h = b.height(b.plane(f), p);
    if (!b.shadow_) approx = to_double(h);
    return sign_of(h);
  }

  /// Whether p is outside face f: strictly above its plane (no height limit).
  struct Side {
    bool outside;
  };
  struct NoLimit {};
  template <class B>
  static NoLimit outside_limit(const B&, int) {
    return {};
  }
  template <class B>
  static Side classify(B& b, int f, int p, NoLimit) {
    double approx = 0;
    return Side{side(b, f, p, approx) > 0};
  }
  /// Points on a face are on the hull: none is kept.
  struct NearFace {
    void offer(const Side&, int) {}
    template <class B>
    void keep(B&, int) const {}
  };

  /// The eye of face f among its conflict points cf: any is correct; the farthest by the determinant's
  /// estimate.
  template <class B>
  static std::size_t farthest(B& b, int f, const std::vector<int>& cf) {
    std::size_t best = 0;
    double bh = 0;
    for (std::size_t i = 0; i < cf.size(); ++i) {
      double h = 0;
      side(b, f, cf[i], h);
      if (i == 0 || h > bh) {
        bh = h;
        best = i;
      }
    }
    return best;
  }
  /// Whether the eye is strictly above face f (a zero-area triangle's side is 0).
  template <class B>
  static bool sees(B& b, int f, int eye) {
    double approx = 0;
    return side(b, f, eye, approx) > 0;
  }
  /// Whether a face the eye does not see joins the visible region when two neighbours are visible: only a
  /// zero-area one.
  template <class B>
  static bool may_join(B&, int, int, bool flat_tri) {
    return flat_tri;
  }
  /// Whether triangle f has zero area, exactly (filtered for double points).
  template <class B>
  static bool zero_area(B& b, int f) {
    const auto& t = b.tris_[as_index(f)];
    if (b.shadow_ && hull::certainly_nonzero_cross(b.qd_[as_index(t.v[0])], b.qd_[as_index(t.v[1])],
                                                   b.qd_[as_index(t.v[2])]))
      return false;
    return is_zero(b.plane(f).normal);
  }
  /// A new triangle's plane, exactly; with double points only when first needed (Builder::plane).
  template <class B, class Tri>
  static void set_plane(B& b, Tri& t, int p0, int p1, int p2) {
    if (!b.shadow_) assign_plane_through(t.pl, b.local_point(p0), b.local_point(p1), b.local_point(p2));
    t.has_plane = !b.shadow_;
  }

  /// Whether groups x and y (roots) are certainly not coplanar, because a vertex of y's root triangle is
  /// certainly off the plane of x's (a group's plane is its root triangle's when that has area; when it has
  /// none, the filter never decides).  Double points only.
  template <class B>
  static bool certainly_apart(const B& b, int x, int y) {
    if (!b.shadow_) return false;
    const auto& tx = b.tris_[as_index(x)];
    for (int v : b.tris_[as_index(y)].v) {
      const FilteredSign r = orientation_filter(b.qd_[as_index(tx.v[0])], b.qd_[as_index(tx.v[1])],
                                                b.qd_[as_index(tx.v[2])], b.qd_[as_index(v)]);
      if (r.certain) return true;
    }
    return false;
  }
  /// A group's plane is its plane triangle's (Builder::plane), built when first needed: with double points
  /// most groups never need one (zero_area and certainly_apart decide without).
  template <class B, class Group>
  static void init_group_fit(B&, Group&, int) {}
  template <class B, class Group>
  static const Plane<T>& group_plane(B& b, const Group& g) {
    return b.plane(g.plane_tri);
  }
  /// Two adjacent groups are one face when their planes are exactly the same oriented plane.
  template <class B, class Group>
  static bool coplanar(B& b, const Group& ga, const Group& gb) {
    const Plane<T>& pa = group_plane(b, ga);
    const Plane<T>& pb = group_plane(b, gb);
    return is_zero(cross(pa.normal, pb.normal)) && dot(pa.normal, pb.normal) > T(0);
  }
  /// A group's plane is its root triangle's: nothing to refit, no area to keep.
  template <class B, class Group>
  static void refit(const B&, Group&) {}
  /// (no vertex sum to keep)
  template <class B, class Group>
  static void unite_sum(const B&, Group&, const Group&, std::span<const int>) {}
  template <class Group>
  static void add_area(Group&, const Group&) {}
  /// (the plane follows plane_tri)
  template <class Group>
  static void adopt_plane(Group&, const Group&) {}

  /// All points on one line: exactly (c < 0, decided by the caller).
  static bool collinear(const T&, const Vec3<T>&, const T&) { return false; }
  /// A strict left turn t (a triple product) of the flat hull's chain.
  template <class Bound>
  static bool left_turn(const T& t, Bound) {
    return t > T(0);
  }
  /// Whether a face corner with turn (about the face normal) and edges e1, e2 is strictly convex; a reflex
  /// corner is a builder bug.
  template <class B>
  static bool convex_corner(const B&, const T& turn, const Vec3<T>& e1, const Vec3<T>& e2) {
    if (turn < T(0) && !is_zero(cross(e1, e2)))
      throw std::logic_error("convex_hull: reflex corner in an exact hull (a bug)");
    return turn > T(0);
  }
  /// A case only rounding can cause (a non-simple horizon, a collapsed hull, a face that is not a disk):
  /// for exact T a builder bug.
  static void rounding_case(const char* what) { throw std::logic_error(std::string("convex_hull: ") + what); }
};

/// float / double: decisions within eps = Tolerances<T>::kCoplanar x extent, on coordinates relative to the
/// bounding-box centre.
template <Number T>
struct FloatHullTraits {
  /// Points left outside by rounding are measured, pinned and the hull rebuilt (repair.hpp).
  static constexpr bool kRepairs = true;
  /// Points kept near a face (within eps) and the vertices a cone removes are tested again.
  static constexpr bool kRechecksRounding = true;
  /// The output is checked as validation will see it first (precheck.hpp).
  static constexpr bool kPrechecks = true;
  /// Every corner is tested against eps, single triangles too.
  static constexpr bool kTriangleFacesConvex = false;
  /// A point set wider than Tolerances<T>::kHullExtentHigh or narrower than kHullExtentLow is built at a
  /// power of two times its coordinates (working_scale.hpp).
  static constexpr bool kWorkingScale = true;
  /// The flat hull's strict chain then drops corners within eps (polygon_2d.hpp, tolerant_loop).
  static constexpr bool kTolerantChain = true;
  /// Welded points are kept relative to the bounding-box centre (Builder::q_).
  static constexpr bool kLocalIsInput = false;
  /// A face group keeps its area-weighted plane, refitted as groups unite (FaceGroup::fit).
  static constexpr bool kRefits = true;
  static constexpr const char* kWeldNote = " (points closer than the weld tolerance)";
  static constexpr const char* kFlatNote = " (within the flat tolerance)";
  static constexpr const char* kLineNote = " (within tolerance)";

  /// The tolerances of the extent (BadScale when the extent overflows plane computations: a triple product
  /// of differences is up to 8 extent^3, a squared length up to 4 extent^2); decisions are made on
  /// coordinates relative to the box centre.
  template <class B>
  static void scale(B& b, const Vec3<T>& lo, const Vec3<T>& hi) {
    const double extent = b.extent_;
    if (!std::isfinite(extent) || !std::isfinite(extent * extent * extent * 8.0) ||
        !number_traits<T>::is_finite(static_cast<T>(extent * extent * 4.0))) {
      throw InvalidInput(ErrorCode::BadScale, "convex_hull: the point set's extent " + format_number(extent) +
                                                  " overflows " + std::string(number_traits<T>::name) +
                                                  " in plane computations");
    }
    const T two(2);
    b.centre_ = Vec3<T>((lo[0] + hi[0]) / two, (lo[1] + hi[1]) / two, (lo[2] + hi[2]) / two);
    b.eps_ = static_cast<T>(Tolerances<T>::kCoplanar * extent);
    b.flat_ = static_cast<T>(Tolerances<T>::kFlat * extent);
    b.weld_ = static_cast<T>(Tolerances<T>::kWeld * extent);
  }
  /// The points welding works on: each input point minus the centre.
  template <class B>
  static std::vector<Vec3<T>> local_points(const B& b) {
    std::vector<Vec3<T>> loc;
    loc.reserve(b.in_.size());
    for (const auto& p : b.in_) loc.push_back(Vec3<T>(p - b.centre_));
    return loc;
  }

  /// Sweep in x: a point is welded to an earlier representative within weld (loc sorted lexicographically
  /// by order).
  template <class B>
  static void weld(B& b, const std::vector<Vec3<T>>& loc, const std::vector<int>& order) {
    const T w2 = b.weld_ * b.weld_;
    std::size_t window = 0;  // first representative with x >= current x - weld
    for (int i : order) {
      const Vec3<T>& p = loc[as_index(i)];
      while (window < b.q_.size() && b.q_[window][0] < p[0] - b.weld_) ++window;
      bool dup = false;
      for (std::size_t r = window; r < b.q_.size() && !dup; ++r) {
        const Vec3<T> d(b.q_[r] - p);
        dup = squared_norm(d) <= w2;
      }
      if (!dup) b.add_point(i, p);
    }
  }
  template <class B>
  static void shadow(B&, const std::vector<Vec3<T>>&) {}

  static T length(const Vec3<T>& v) { return number_traits<T>::sqrt(squared_norm(v)); }

  /// p's height above face f, and whether that is outside it: more than limit above (eps, or 0 for a point
  /// a repair pass pinned: it becomes a vertex whenever it is outside; Builder::threshold).
  struct Side {
    bool outside;
    T height;
  };
  template <class B>
  static T outside_limit(const B& b, int p) {
    return b.threshold(p);
  }
  template <class B>
  static Side classify(B& b, int f, int p, const T& limit) {
    const T h = b.height(b.tris_[as_index(f)].pl, p);
    return Side{h > limit, h};
  }
  /// A point within eps above a face is on the hull now, but a later eye can replace that face by faces
  /// tilted away from it (a new face through a short horizon edge and an eye barely above the old plane,
  /// extrapolated across a wide thin face, can leave the point hundreds of eps outside): it is kept on the
  /// face it is highest above and tested again when that face is replaced.  Only a point below every face it
  /// was tested against is dropped.
  struct NearFace {
    int face = -1;
    T height = T(0);
    void offer(const Side& s, int f) {
      if (s.height > height) {
        height = s.height;
        face = f;
      }
    }
    template <class B>
    void keep(B& b, int p) const {
      if (face >= 0) b.tris_[as_index(face)].on.push_back(p);
    }
  };

  /// The eye of face f among its conflict points cf: the highest above its plane.
  template <class B>
  static std::size_t farthest(B& b, int f, const std::vector<int>& cf) {
    const auto& pl = b.tris_[as_index(f)].pl;
    std::size_t best = 0;
    T bh = b.height(pl, cf[0]);
    for (std::size_t i = 1; i < cf.size(); ++i) {
      const T h = b.height(pl, cf[i]);
      if (h > bh) {
        bh = h;
        best = i;
      }
    }
    return best;
  }
  /// Whether the eye is above face f (a face with a zero normal has no plane: not seen).
  template <class B>
  static bool sees(B& b, int f, int eye) {
    const auto& nt = b.tris_[as_index(f)];
    return !is_zero(nt.pl.normal) && b.height(nt.pl, eye) > T(0);
  }
  /// Whether a face the eye does not see joins the visible region when two neighbours are visible: a
  /// zero-area one, or one whose plane the eye is (within eps) on: otherwise the two cone triangles over its
  /// edges fold over it, enclosing the vertex between those edges.
  template <class B>
  static bool may_join(B& b, int f, int eye, bool flat_tri) {
    return flat_tri || !(b.height(b.tris_[as_index(f)].pl, eye) < -b.eps_);
  }
  template <class B>
  static bool zero_area(B& b, int f) {
    return is_zero(b.plane(f).normal);
  }
  /// A new triangle's plane, with its apex at the largest angle (opposite the longest edge): the cross
  /// product of the two edges from there loses the least accuracy.
  template <class B, class Tri>
  static void set_plane(B& b, Tri& t, int p0, int p1, int p2) {
    const Vec3<T>& a = b.local_point(p0);
    const Vec3<T>& c1 = b.local_point(p1);
    const Vec3<T>& c2 = b.local_point(p2);
    const T l0 = squared_norm(Vec3<T>(c1 - a));   // opposite p2
    const T l1 = squared_norm(Vec3<T>(c2 - c1));  // opposite p0
    const T l2 = squared_norm(Vec3<T>(a - c2));   // opposite p1
    if (l1 >= l0 && l1 >= l2) {
      t.pl = plane_through(a, c1, c2);
    } else if (l2 >= l0) {
      t.pl = plane_through(c1, c2, a);
    } else {
      t.pl = plane_through(c2, a, c1);
    }
  }

  template <class B>
  static bool certainly_apart(const B&, int, int) {
    return false;
  }
  /// A group's plane starts as its triangle's, and its area as the triangle's area-weighted normal (its area
  /// from the edge lengths, Builder::tri_area2); both are refitted as groups unite (refit, add_area).
  template <class B, class Group>
  static void init_group_fit(B& b, Group& g, int f) {
    g.fit.pl = b.plane(f);
    g.fit.area = T(2) * number_traits<T>::sqrt(b.tri_area2(b.tris_[as_index(f)])) * g.fit.pl.normal;
    g.fit.sum = Vec3<double>(0, 0, 0);
    for (int v : g.verts) g.fit.sum += vec_to_double(b.local_point(v));
  }
  /// gx's vertex sum (what refit reads) once gy joins it, the vertices in shared counted once.
  template <class B, class Group>
  static void unite_sum(const B& b, Group& gx, const Group& gy, std::span<const int> shared) {
    gx.fit.sum += gy.fit.sum;
    for (int v : shared) gx.fit.sum -= vec_to_double(b.local_point(v));
  }
  template <class B, class Group>
  static const Plane<T>& group_plane(const B&, const Group& g) {
    return g.fit.pl;
  }
  /// Either face sees every vertex of the other (not shared with it) less than eps below its plane.
  /// (Either: a thin face's own plane is poorly determined, so the other face's plane may be the one that
  /// tells.)
  template <class B, class Group>
  static bool coplanar(const B& b, const Group& ga, const Group& gb) {
    auto close = [&](const Group& g, const Group& h) {
      for (int v : h.verts) {
        if (std::binary_search(g.verts.begin(), g.verts.end(), v)) continue;
        if (!(b.height(g.fit.pl, v) > -b.eps_)) return false;
      }
      return true;
    };
    return close(ga, gb) || close(gb, ga);
  }
  /// The group's plane: its area-weighted normal through the mean of its vertices (from their sum in
  /// double, kept as vertices join: O(1) a union).
  template <class B, class Group>
  static void refit(const B&, Group& g) {
    Vec3<T> n = g.fit.area;
    const T len = length(n);
    if (len > T(0)) n = Vec3<T>(n[0] / len, n[1] / len, n[2] / len);
    const T off = static_cast<T>(dot(vec_to_double(n), g.fit.sum) / static_cast<double>(g.verts.size()));
    g.fit.pl = Plane<T>{n, off};
  }
  template <class Group>
  static void add_area(Group& gx, const Group& gy) {
    gx.fit.area = Vec3<T>(gx.fit.area + gy.fit.area);
  }
  /// A degenerate group joining a group with area takes its plane.
  template <class Group>
  static void adopt_plane(Group& gx, const Group& gy) {
    gx.fit.pl = gy.fit.pl;
  }

  /// All points within flat x extent of line ab: far2 = |ab x ac|^2 for the farthest point c, its distance
  /// |ab x ac| / |ab|.
  static bool collinear(const T& far2, const Vec3<T>& ab, const T& flat) {
    return number_traits<T>::sqrt(far2) <= flat * length(ab);
  }
  /// A left turn t of the flat hull's chain by more than bound() (eps times the normal's and the longer
  /// edge's lengths: the distance of either end from the other edge's line is more than eps).
  template <class Bound>
  static bool left_turn(const T& t, Bound bound) {
    return t > bound();
  }
  /// Whether a face corner is convex by more than eps (its distance from the line through its neighbours).
  template <class B>
  static bool convex_corner(const B& b, const T& turn, const Vec3<T>& e1, const Vec3<T>& e2) {
    return turn > b.eps_ * std::max(length(e1), length(e2));
  }
  static void rounding_case(const char*) {}
};

/// The hull traits of T.
template <Number T>
using HullTraits = std::conditional_t<number_traits<T>::is_exact, ExactHullTraits<T>, FloatHullTraits<T>>;

}  // namespace sepax::hull::detail
