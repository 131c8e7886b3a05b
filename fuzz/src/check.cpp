// The checking core: see sepax/fuzz/check.hpp.
#include <sepax/fuzz/check.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>
#include <sstream>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <sepax/robust/number_types.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/orientation_filter.hpp>
#include <sepax/fuzz/error_bounds.hpp>
#include <sepax/fuzz/sat_list.hpp>
#include <sepax/fuzz/classify.hpp>
#include <sepax/fuzz/check_manifold.hpp>
#include <sepax/fuzz/bitwise.hpp>
#include <sepax/fuzz/check_posed.hpp>
#include <sepax/fuzz/recorder.hpp>

namespace sepax::fuzz {

const char* classification_name(Classification k) {
  switch (k) {
    case Classification::agree:
      return "agree";
    case Classification::exact_zero:
      return "exact_zero";
    case Classification::explained:
      return "explained";
    case Classification::tie:
      return "tie";
    case Classification::unexplained:
      return "unexplained";
    case Classification::nonconvex:
      return "nonconvex";
  }
  return "?";
}

bool has_robust_policy() { return SEPAX_FUZZ_HAS_ROBUST != 0; }
bool has_traversal_sat() { return SEPAX_FUZZ_HAS_TRAVERSAL != 0; }

using Q = mpq_class;

// ---- exact comparisons of a rational against a separation num/sqrt(norm2) ----

// sign(r - num/sqrt(n2)), exactly.
int cmp_rational_sep(const Q& r, const Separation<Q>& s) {
  const int sr = sign_of(r), sv = sign_of(s.num);
  if (sr != sv) return sr < sv ? -1 : 1;
  if (sr == 0) return 0;
  const Q lhs = r * r * s.norm2, rhs = s.num * s.num;
  const int mag = (lhs > rhs) - (lhs < rhs);
  return sr > 0 ? mag : -mag;
}

// |x - value(s)| <= bound, exactly (bound as the rational value of a double).
bool within(double x, const Separation<Q>& s, double bound) {
  if (!std::isfinite(bound)) return true;
  const Q qx(x), qb(bound);
  return cmp_rational_sep(Q(qx - qb), s) <= 0 && cmp_rational_sep(Q(qx + qb), s) >= 0;
}

// sign(value(x) - value(y) - b), exactly, for x = p/sqrt(m), y = q/sqrt(n)
// (m, n > 0) and a rational b.  Multiplying by sqrt(m n) > 0 it is the sign of
//   X - Y,   X = p sqrt(n) - q sqrt(m),   Y = b sqrt(m n).
// sign(X) compares p sqrt(n) with q sqrt(m): signs first, then p^2 n vs q^2 m.
// When sign(X) != sign(Y) that decides it; when both are s != 0, compare the
// squares: X^2 - Y^2 = R - S sqrt(m n) with R = p^2 n + q^2 m - b^2 m n and
// S = 2 p q, whose sign is again signs first, then R^2 vs S^2 m n; times s.
// Every step is a rational comparison: nothing goes through double.
int sign_sep_diff(const Separation<Q>& x, const Separation<Q>& y, const Q& b) {
  const Q &p = x.num, &m = x.norm2, &q = y.num, &n = y.norm2;
  // sign(u sqrt(a) - v sqrt(c)) for rationals u, v and a, c >= 0
  auto sign_sqrt_diff = [](const Q& u, const Q& a, const Q& v, const Q& c) {
    const int su = sgn(u) * sgn(a), sv = sgn(v) * sgn(c);
    if (su != sv) return su < sv ? -1 : 1;
    if (su == 0) return 0;
    const Q lhs = u * u * a, rhs = v * v * c;
    const int mag = (lhs > rhs) - (lhs < rhs);
    return su > 0 ? mag : -mag;
  };
  const int sx = sign_sqrt_diff(p, n, q, m);
  const int sy = sgn(b);  // sqrt(m n) > 0
  if (sx != sy) return sx < sy ? -1 : 1;
  if (sx == 0) return 0;
  const Q mn = m * n;
  const Q R = p * p * n + q * q * m - b * b * mn;
  const Q S = 2 * p * q;
  // sign(X^2 - Y^2) = sign(R - S sqrt(mn)) = sign_sqrt_diff(R, 1, S, mn)
  const int sq = sign_sqrt_diff(R, Q(1), S, mn);
  return sx > 0 ? sq : -sq;
}

// Does x exceed y by more than the bound b (value(x) - value(y) > b),
// exactly?  An infinite (or NaN) bound never lets it: a bound that is not
// finite shows nothing (as in within and close), and it has no rational value.
bool beats(const Separation<Q>& x, const Separation<Q>& y, double b) {
  return std::isfinite(b) && sign_sep_diff(x, y, Q(b)) > 0;
}

// |value(x) - value(y)| <= bound for two exact separations with (possibly)
// different axis norms, decided exactly (sign_sep_diff): equal values always
// hold, an infinite bound always holds, and the bound is the rational value of
// the double.  Nothing goes through double.
bool close(const Separation<Q>& x, const Separation<Q>& y, double bound) {
  if (!std::isfinite(bound)) return true;
  if (sepax::compare(x, y) == 0) return true;
  const Q b(bound);
  return sign_sep_diff(x, y, b) <= 0 && sign_sep_diff(y, x, b) <= 0;
}

Classification classify_sign(int float_sign, const ExactSep& exact, double bound, bool exact_decisions) {
  const int es = sign(exact);
  if (float_sign == es) return Classification::agree;
  if (exact_decisions) return Classification::unexplained;
  if (es == 0) return Classification::exact_zero;
  return within(0.0, exact, bound) ? Classification::explained : Classification::unexplained;
}

Classification classify_overlap(bool float_overlap, bool exact_overlap, const ExactSep& exact_max,
                                double bound, bool exact_decisions) {
  if (float_overlap == exact_overlap) return Classification::agree;
  if (exact_decisions) return Classification::unexplained;
  if (sign(exact_max) == 0) return Classification::exact_zero;
  return within(0.0, exact_max, bound) ? Classification::explained : Classification::unexplained;
}

Classification classify_separation(double sf, const ExactSep& exact_max, bool same_axis, double bf, double be,
                                   bool exact_decisions) {
  if (cmp_rational_sep(mpq_class(sf), exact_max) == 0) return Classification::agree;
  if (same_axis) {
    if (!within(sf, exact_max, bf)) return Classification::unexplained;
    return sign(exact_max) == 0 ? Classification::exact_zero : Classification::explained;
  }
  if (exact_decisions) return Classification::unexplained;
  return within(sf, exact_max, bf + be) ? Classification::tie : Classification::unexplained;
}

namespace {

using CPQ = ConvexPolyhedron<Q>;

std::string num(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

// ---- the exact reference ----
struct Exact {
  CPQ A, B;
  std::unique_ptr<PlainKernel<Q>> k;
  SatResult<Q> ref;
  std::vector<FaceQuery<Q>> fqA, fqB;
  std::vector<ArcSigns> arcs;        // ea * EB + eb
  std::vector<double> nlenA, nlenB;  // lower bounds on |N_e| per face
  // Is the exact image exactly convex (every face's vertices exactly on the
  // plane through its plane triple, every vertex on or below every face)?
  // When it is not, each SAT is checked against the exact run of the same
  // SAT (ref_by_sat, filled by the mpq pass), and cross-SAT differences are
  // classified Classification::nonconvex (see check.hpp).
  bool convex = true;
  std::array<std::optional<SatResult<Q>>, 3> ref_by_sat;
  // The exact Gauss-map axis k->axis(Feature::edges(ea, eb)) of every edge
  // pair that is an exact Minkowski face (arcs) and not exactly parallel
  // (k->edges_parallel), by pair index ea * EB + eb (fill_minkowski_axes).
  // The four float configurations' axis_side comparisons and decision checks
  // read these instead of each computing the same rational cross products:
  // the same kernel functions on the same exact images give the same values.
  std::unordered_map<std::size_t, Vec3<Q>> minkowski_axes;

  /// The index of edge pair (ea, eb) in arcs and minkowski_axes: ea * EB + eb.
  std::size_t pair_index(int ea, int eb) const {
    return static_cast<std::size_t>(ea) * static_cast<std::size_t>(B.edge_count()) +
           static_cast<std::size_t>(eb);
  }

  void fill_minkowski_axes() {
    for (int ea = 0; ea < A.edge_count(); ++ea)
      for (int eb = 0; eb < B.edge_count(); ++eb) {
        const std::size_t i = pair_index(ea, eb);
        if (arcs[i].minkowski_face() && !k->edges_parallel(ea, eb))
          minkowski_axes.emplace(i, k->axis(Feature::edges(ea, eb)));
      }
  }
  /// The exact axis of edge pair (ea, eb) when it is an exact Minkowski face
  /// that is not exactly parallel; null otherwise.
  const Vec3<Q>* minkowski_axis(int ea, int eb) const {
    const auto it = minkowski_axes.find(pair_index(ea, eb));
    return it == minkowski_axes.end() ? nullptr : &it->second;
  }
  /// k->axis(f), read from minkowski_axes when it is there.
  Vec3<Q> axis(const Feature& f) const {
    if (f.type == FeatureType::EdgePair)
      if (const Vec3<Q>* x = minkowski_axis(f.a, f.b)) return *x;
    return k->axis(f);
  }

  const SatResult<Q>& ref_for(Sat sat) const {
    const auto& r = ref_by_sat[static_cast<std::size_t>(sat)];
    return (!convex && r) ? *r : ref;
  }
  /// The comparison with ref_for(sat) crosses SATs on a non-convex input.
  bool cross_sat(Sat sat) const {
    return !convex && sat != Sat::gauss_map && !ref_by_sat[static_cast<std::size_t>(sat)];
  }
};

// The kernel of the reference run (mpq + gauss_map): PlainKernel<mpq> on the
// exact images, with two of its steps read from values the reference has
// already computed, each the value the kernel would compute itself (so the run
// and its result are the same):
//   * minkowski_faces: the Minkowski-face verdict of every edge pair from
//     E.arcs (exact_arc_signs), whose four signs are PlainKernel<mpq>::arc_signs'
//     (signs of the same triple products times a positive power of two;
//     tests/fuzz/classify_test.cpp compares them), and HasMinkowskiFaces asks
//     for exactly arc_signs(ea, eb).minkowski_face() (sat_kernel.hpp).  The
//     Gauss map's O(E_A E_B) rational arc tests are what this removes.
//   * face_query_a, face_query_b: E.fqA, E.fqB, which are this kernel's
//     face_query_a, face_query_b.
//   * edges_parallel and edge_separation of a pair that E.arcs makes a
//     Minkowski face (the only pairs the Gauss map measures): parallel when
//     E.minkowski_axes has no axis for it (it holds this kernel's axis of
//     every such pair that is not exactly parallel), and the separation
//     PlainKernel<mpq>::edge_separation computes from that axis n (its
//     edge_axis): dot(n, tail_B - tail_A) over squared_norm(n), in rationals,
//     so the same values.
class ReferenceKernel : public PlainKernel<Q> {
 public:
  explicit ReferenceKernel(const Exact& e) : PlainKernel<Q>(e.A, e.B), e_(e) {}

  FaceQuery<Q> face_query_a(int f) const { return e_.fqA[static_cast<std::size_t>(f)]; }
  FaceQuery<Q> face_query_b(int f) const { return e_.fqB[static_cast<std::size_t>(f)]; }

  bool edges_parallel(int ea, int eb) const {
    if (!e_.arcs[e_.pair_index(ea, eb)].minkowski_face()) return PlainKernel<Q>::edges_parallel(ea, eb);
    return e_.minkowski_axis(ea, eb) == nullptr;
  }

  Separation<Q> edge_separation(int ea, int eb) const {
    const Vec3<Q>* n = e_.minkowski_axis(ea, eb);
    if (n == nullptr) return PlainKernel<Q>::edge_separation(ea, eb);
    const Vec3<Q>& pa = e_.A.vertex(e_.A.edge_tail(ea));
    const Vec3<Q>& pb = e_.B.vertex(e_.B.edge_tail(eb));
    return Separation<Q>{dot(*n, Vec3<Q>(Q(pb[0] - pa[0]), Q(pb[1] - pa[1]), Q(pb[2] - pa[2]))),
                         squared_norm(*n)};
  }

  int minkowski_faces(int ea, int lo, int hi, int* out) const {
    const ArcSigns* row = e_.arcs.data() + e_.pair_index(ea, 0);
    int n = 0;
    for (int eb = lo; eb < hi; ++eb)
      if (row[eb].minkowski_face()) out[n++] = eb;
    return n;
  }

 private:
  const Exact& e_;
};
static_assert(SatKernel<ReferenceKernel> && HasMinkowskiFaces<ReferenceKernel>);

}  // namespace

// The exact side of vertex v of face f's plane in the exact image of p:
// sign(N.v - offset) with N = (t1 - t0) x (t2 - t0) of the plane triple t
// and offset N.t0 (ConvexPolyhedron<mpq>'s plane), that is
// sign det[t1 - t0, t2 - t0, v - t0].  The core's semi-static filter
// (orientation_filter.hpp) decides it when it can; otherwise rationals do.
// Vertices of the triple are exactly on it.  (A flat shape's back face has
// the reversed triple: the front plane negated, as ConvexPolyhedron has it.)
static int exact_plane_side(const ConvexPolyhedron<float>& p, int f, int v) {
  const auto& t = p.face(f).plane_vertices;
  if (v == t[0] || v == t[1] || v == t[2]) return 0;
  const Vec3<float>&a = p.vertex(t[0]), &b = p.vertex(t[1]), &c = p.vertex(t[2]), &x = p.vertex(v);
  const FilteredSign s =
      orientation_filter(vec_cast<double>(a), vec_cast<double>(b), vec_cast<double>(c), vec_cast<double>(x));
  if (s.certain) return s.det > 0 ? 1 : -1;
  const Vec3<Q> qa = vec_cast<Q>(a);
  return sgn(Q(
      dot(cross(Vec3<Q>(vec_cast<Q>(b) - qa), Vec3<Q>(vec_cast<Q>(c) - qa)), Vec3<Q>(vec_cast<Q>(x) - qa))));
}

bool exactly_convex(const ConvexPolyhedron<float>& p) {
  for (int f = 0; f < p.face_count(); ++f) {
    for (int v : p.face_vertices(f))
      if (exact_plane_side(p, f, v) != 0) return false;
    for (int v = 0; v < p.vertex_count(); ++v)
      if (exact_plane_side(p, f, v) > 0) return false;
  }
  return true;
}

namespace {

// The exact projections of both shapes on N = eA x eB (the brute force's
// unnormalised axis) and the two gaps: plus (A below B along N) and minus.
struct EdgeGaps {
  Vec3<Q> N;
  Q la, ha, lb, hb;
  Separation<Q> plus() const { return {Q(lb - ha), squared_norm(N)}; }
  Separation<Q> minus() const { return {Q(la - hb), squared_norm(N)}; }
};
EdgeGaps exact_edge_gaps(const Exact& E, int ea, int eb) {
  EdgeGaps g;
  g.N = cross(E.A.edge_direction(ea), E.B.edge_direction(eb));
  auto proj = [&](const CPQ& p, Q& lo, Q& hi) {
    lo = hi = dot(g.N, p.vertex(0));
    for (int i = 1; i < p.vertex_count(); ++i) {
      const Q h = dot(g.N, p.vertex(i));
      if (h < lo) lo = h;
      if (h > hi) hi = h;
    }
  };
  proj(E.A, g.la, g.ha);
  proj(E.B, g.lb, g.hb);
  return g;
}

// The exact projection value of edge pair (ea, eb), the larger of both gaps.
Separation<Q> exact_edge_projection(const Exact& E, int ea, int eb) {
  const EdgeGaps g = exact_edge_gaps(E, ea, eb);
  return sepax::compare(g.plus(), g.minus()) >= 0 ? g.plus() : g.minus();
}

// The exact separation of a feature as the given SAT defines it.
Separation<Q> exact_value(const Exact& E, Sat sat, const Feature& f) {
  switch (f.type) {
    case FeatureType::FaceA:
      return E.fqA[static_cast<std::size_t>(f.a)].separation;
    case FeatureType::FaceB:
      return E.fqB[static_cast<std::size_t>(f.b)].separation;
    case FeatureType::EdgePair:
      return sat == Sat::brute_force ? exact_edge_projection(E, f.a, f.b) : E.k->edge_separation(f.a, f.b);
    case FeatureType::SideA:
      return E.k->side_query_a(f.a).separation;
    case FeatureType::SideB:
      return E.k->side_query_b(f.b).separation;
  }
  return {};
}

// The exact height of vertex v of q along the side axis of edge e of p (the
// same value num / sqrt(norm2) as PlainKernel<Q>::side_query gives its support
// vertex): u = (head - tail) x N, N the exact plane normal of edge_face(e, 0).
Separation<Q> exact_side_height(const CPQ& p, int e, const CPQ& q, int v) {
  const Vec3<Q> u = cross(p.edge_direction(e), p.plane(p.edge_face(e, 0)).normal);
  return {dot(u, Vec3<Q>(q.vertex(v) - p.vertex(p.edge_tail(e)))), squared_norm(u)};
}

bool same_axis(const Feature& x, const Feature& y) {
  return x.type == y.type && x.primary() == y.primary() && x.secondary() == y.secondary();
}

template <class F>
Vec3<F> unit_axis(const Vec3<F>& da, const Vec3<F>& db) {
  Vec3<F> n = cross(da, db);
  const F len = std::sqrt(squared_norm(n));
  return Vec3<F>(n[0] / len, n[1] / len, n[2] / len);
}

template <class F>
struct FloatSide {
  const ConvexPolyhedron<F>& A;
  const ConvexPolyhedron<F>& B;
  const Exact& E;
  std::vector<double> deltaA, deltaB;  // (1) per face

  FloatSide(const ConvexPolyhedron<F>& a, const ConvexPolyhedron<F>& b, const Exact& e) : A(a), B(b), E(e) {
    auto fill = [](const ConvexPolyhedron<F>& p, const std::vector<double>& nlen, std::vector<double>& out) {
      for (int f = 0; f < p.face_count(); ++f) {
        const auto pts = p.plane_points(f);
        out.push_back(bounds::delta_normal<F>(Vec3<F>(pts[1] - pts[0]), Vec3<F>(pts[2] - pts[0]),
                                              nlen[static_cast<std::size_t>(f)]));
      }
    };
    fill(A, E.nlenA, deltaA);
    fill(B, E.nlenB, deltaB);
  }

  double face_bound(const ConvexPolyhedron<F>& p, const std::vector<double>& delta, int f,
                    const ConvexPolyhedron<F>& q) const {
    double m = 0;
    const auto& n = p.plane(f).normal;
    const auto p0 = p.plane_points(f)[0];
    for (const auto& v : q.vertices())
      m = std::max(m, bounds::face_bound<F>(n, p0, v, delta[static_cast<std::size_t>(f)]));
    return m;
  }

  double edge_delta(int ea, int eb) const {
    const Vec3<Q> ne = cross(E.A.edge_direction(ea), E.B.edge_direction(eb));
    return bounds::delta_normal<F>(A.edge_direction(ea), B.edge_direction(eb),
                                   bounds::sqrt_lower(squared_norm(ne).get_d()));
  }

  // Forward error bound of the separation the given SAT reports for feature f.
  double bound(Sat sat, const Feature& f) const {
    switch (f.type) {
      case FeatureType::FaceA:
        return face_bound(A, deltaA, f.a, B);
      case FeatureType::FaceB:
        return face_bound(B, deltaB, f.b, A);
      case FeatureType::EdgePair: {
        const Vec3<F> da = A.edge_direction(f.a), db = B.edge_direction(f.b);
        const double dn = edge_delta(f.a, f.b);
        const Vec3<F> n = unit_axis(da, db);
        if (sat != Sat::brute_force) {
          const Vec3<F> w(B.vertex(B.edge_tail(f.b)) - A.vertex(A.edge_tail(f.a)));
          return bounds::edge_bound<F>(n, w, dn);
        }
        double m = 0, mag = 0;
        for (const auto* p : {&A, &B})
          for (const auto& v : p->vertices()) {
            m = std::max(m, bounds::projection_bound<F>(n, v, dn));
            mag = std::max(mag, std::abs(double(dot(n, v))));
          }
        const double u = bounds::u_of<F>();
        return (2 * m + 2 * u * mag * (1 + bounds::gamma(1, u))) * bounds::kSlack;
      }
      case FeatureType::SideA:
        return side_bound(A, deltaA, f.a, B);
      case FeatureType::SideB:
        return side_bound(B, deltaB, f.b, A);
    }
    return 0;
  }

  // (8) of error_bounds.hpp: may the plain kernel orient the Gauss-map axis
  // of (ea, eb) the other way from exact arithmetic?  |S_e| <= B_or, exactly.
  bool orientation_may_flip(int ea, int eb) const {
    const Vec3<F> n = unit_axis(A.edge_direction(ea), B.edge_direction(eb));
    const Vec3<F>& pa = A.vertex(A.edge_tail(ea));
    const Vec3<F>& pb = B.vertex(B.edge_tail(eb));
    const Vec3<F> wa(pa - A.centroid()), wb(B.centroid() - pb);
    const double b = bounds::orientation_bound<F>(n, wa, wb, edge_delta(ea, eb), bounds::centroid_error<F>(A),
                                                  bounds::centroid_error<F>(B));
    const Vec3<Q> N = cross(E.A.edge_direction(ea), E.B.edge_direction(eb));
    const Vec3<Q> X = Vec3<Q>(E.A.vertex(E.A.edge_tail(ea)) - E.A.centroid()) +
                      Vec3<Q>(E.B.centroid() - E.B.vertex(E.B.edge_tail(eb)));
    return within(0.0, Separation<Q>{dot(N, X), squared_norm(N)}, b);
  }

  // (9) of error_bounds.hpp: may the plain brute force accept (ea, eb) in
  // orientation plus (A's edge at A's maximum along eA x eB, B's at B's
  // minimum) or minus?  Every endpoint within the "possible" band, exactly.
  bool support_may_accept(int ea, int eb, bool plus, const EdgeGaps& g) const {
    const Vec3<F> n = unit_axis(A.edge_direction(ea), B.edge_direction(eb));
    const double dn = edge_delta(ea, eb);
    // the band half-width of shape p at its maximum (hi) or minimum
    auto width = [&](const ConvexPolyhedron<F>& p, bool hi) {
      double ps = 0;
      F lo_f = dot(n, p.vertex(0)), hi_f = lo_f;
      for (const auto& v : p.vertices()) {
        ps = std::max(ps, bounds::projection_bound<F>(n, v, dn));
        const F h = dot(n, v);
        lo_f = std::min(lo_f, h);
        hi_f = std::max(hi_f, h);
      }
      const double t = double(PlainKernel<F>::support_tolerance(p));
      return bounds::support_band_width<F>(t, ps, std::abs(double(hi ? hi_f : lo_f)));
    };
    const Q n2 = squared_norm(g.N);
    // depth of endpoint v below the extreme ext (sign s: +1 at a maximum)
    auto near = [&](const Vec3<Q>& v, const Q& ext, int s, double w) {
      return within(0.0, Separation<Q>{Q(s * (ext - dot(g.N, v))), n2}, w);
    };
    const double wa = width(A, plus), wb = width(B, !plus);
    const Vec3<Q>&ta = E.A.vertex(E.A.edge_tail(ea)), &ha = E.A.vertex(E.A.edge_head(ea));
    const Vec3<Q>&tb = E.B.vertex(E.B.edge_tail(eb)), &hb = E.B.vertex(E.B.edge_head(eb));
    if (plus)
      return near(ta, g.ha, 1, wa) && near(ha, g.ha, 1, wa) && near(tb, g.lb, -1, wb) &&
             near(hb, g.lb, -1, wb);
    return near(ta, g.la, -1, wa) && near(ha, g.la, -1, wa) && near(tb, g.hb, 1, wb) && near(hb, g.hb, 1, wb);
  }

  // (7) of error_bounds.hpp: the side axis of edge e of p against q's vertices.
  double side_bound(const ConvexPolyhedron<F>& p, const std::vector<double>& delta, int e,
                    const ConvexPolyhedron<F>& q) const {
    return bounds::side_axis_bound<F>(p, e, q, delta[static_cast<std::size_t>(p.edge_face(e, 0))]);
  }
};

const char* side_name(int i) {
  static const char* names[] = {"cba = sign(nB0.eA)", "dba = sign(nB1.eA)", "adc = -sign(nA0.eB)",
                                "bdc = -sign(nA1.eB)"};
  return names[i];
}

// Is the float Gauss-map orientation of edge pair f the other one from exact
// arithmetic's?  (Both kernels' axis(): the float's is a unit vector within
// its small error of +-the exact axis.)
template <class K>
bool orientation_flipped(const K& k, const Exact& E, const Feature& f) {
  return sgn(dot(vec_cast<Q>(k.axis(f)), E.axis(f))) <= 0;
}

// Does the exact brute force accept edge pair f in orientation plus / minus
// (both endpoints exactly at their shapes' extremes along N)?
bool exactly_supported(const Exact& E, const EdgeGaps& g, const Feature& f, bool plus) {
  auto at = [&](const CPQ& p, int e, const Q& ext) {
    return dot(g.N, p.vertex(p.edge_tail(e))) == ext && dot(g.N, p.vertex(p.edge_head(e))) == ext;
  };
  return plus ? at(E.A, f.a, g.ha) && at(E.B, f.b, g.lb) : at(E.A, f.a, g.la) && at(E.B, f.b, g.hb);
}

// The decision model of a plain run, used when the usual rules leave a
// difference unexplained.  A plain kernel decides a few things differently
// from exact arithmetic, each within a band error_bounds.hpp derives:
//   (2) an arc test accepts or rejects an edge pair (compared per pair as
//       arc_sign / minkowski_face);
//   (6) a nearly parallel edge pair is skipped;
//   (8) a Gauss-map edge axis is oriented the other way (compared per pair as
//       axis_side);
//   (9) the brute force accepts a pair within its support tolerance;
//   (10) on an input whose exact image is not exactly convex, the
//       traversal skips an arc of A by its arc bound (docs/traversal.md,
//       step 3: every pair on the arc is at most max(height(f0, x),
//       height(f1, x)) for a vertex x of B), or the rest of an arc after a
//       crossing by the same bound with x the vertex it entered, which
//       hold only for exactly convex shapes: a pair beyond its choice is
//       explained when its arc was prunable by the best it reported
//       (arc_prunable, rest_prunable).
// The SAT's result is explained by them when
//   (i)   its value sf is within its bound bf of the exact value of its
//         feature as its kernel decided it (own: the flipped axis's value for
//         (8), the accepted orientation's gap for (9)), each such decision
//         within its band, and its overlap verdict is the one that value
//         implies (exactly or within bf);
//   (ii)  own reaches, within bf and that candidate's bound, the exact value
//         (as the kernel decided it) of every candidate the kernel measured:
//         every face, every side axis, every edge pair it did not skip;
//   (iii) every exact candidate it did not measure whose exact value beats
//         own by more than both bounds was skipped within a band: (6) for a
//         parallel skip, (2) for an arc test (classified per pair); a brute
//         force that rejects an exactly supported pair is not modelled.
struct DecisionCheck {
  bool ok = false;
  std::string why;
};

// Is the exact height of B's vertex x over A's face f not beyond best, by
// more than the traversal's bound on that height?
template <class F>
bool height_not_beyond(const FloatSide<F>& S, int f, int x, const Separation<Q>& best) {
  return !beats(S.E.k->face_separation_a(f, x), best, S.bound(Sat::traversal, Feature::face_a(f, x)));
}

// (10): could a traversal whose best ended at the computed value sf have
// skipped the arc of A's edge ea by the arc bound?  It skips it when some
// vertex x of B has both computed heights over the arc's faces f0, f1 below
// its best at that time, which is at most sf; a computed height is within
// its face bound of the exact one, so x must have both exact heights below
// sf + that bound.  Decided exactly.
template <class F>
bool arc_prunable(const FloatSide<F>& S, int ea, double sf) {
  const Exact& E = S.E;
  const int f0 = E.A.edge_face(ea, 0), f1 = E.A.edge_face(ea, 1);
  const Separation<Q> best{Q(sf), Q(1)};
  for (int x = 0; x < E.B.vertex_count(); ++x)
    if (height_not_beyond(S, f0, x, best) && height_not_beyond(S, f1, x, best)) return true;
  return false;
}

// The exact value of edge pair f as kernel k decided it: along the exact
// axis, or against it when k's axis is oriented the other way (8).
template <class K>
Separation<Q> value_as_decided(const K& k, const Exact& E, const Feature& f) {
  const Separation<Q> x = E.k->edge_separation(f.a, f.b);
  return orientation_flipped(k, E, f) ? Separation<Q>{Q(-x.num), x.norm2} : x;
}

// (10), the rest of a walk: after a crossing (ea, eb') below its best, the
// walk ends when the vertex it entered (an end x of eb') is below its best
// over the face the walk ends at (docs/traversal.md, step 3, "rest of the
// walk"): could that have ended the walk of arc ea at the computed value sf?
// It could when some pair (ea, eb') the kernel takes is, at its exact value
// as the kernel decided it, not beyond sf, and an end x of eb' has an exact
// height over f0 or f1 not beyond sf (each within its bound).  Decided
// exactly.
template <class F, class K>
bool rest_prunable(const FloatSide<F>& S, const K& k, int ea, double sf) {
  const Exact& E = S.E;
  const int f0 = E.A.edge_face(ea, 0), f1 = E.A.edge_face(ea, 1);
  const Separation<Q> best{Q(sf), Q(1)};
  for (int eb = 0; eb < E.B.edge_count(); ++eb) {
    if (k.edges_parallel(ea, eb) || !k.minkowski_face(ea, eb)) continue;
    const Feature f = Feature::edges(ea, eb);
    if (beats(value_as_decided(k, E, f), best, S.bound(Sat::traversal, f))) continue;
    for (const int y : {E.B.edge_tail(eb), E.B.edge_head(eb)})
      if (height_not_beyond(S, f0, y, best) || height_not_beyond(S, f1, y, best)) return true;
  }
  return false;
}

template <class F, class Policy>
DecisionCheck decision_check(const FloatSide<F>& S, Sat sat, const SatResult<F>& r, double bf) {
  const Exact& E = S.E;
  const ConvexPolyhedron<F>&A = S.A, &B = S.B;
  const kernel_t<Policy, F> k(A, B);
  const Feature& ff = r.feature;
  const double sf = r.separation_as_double();
  const bool brute = sat == Sat::brute_force;
  DecisionCheck d;
  auto fail = [&](std::string why) {
    d.why = std::move(why);
    return d;
  };
  // (i)
  std::optional<Separation<Q>> own;
  if (ff.type == FeatureType::EdgePair && !brute) {
    const Separation<Q> x = E.k->edge_separation(ff.a, ff.b);
    if (!orientation_flipped(k, E, ff)) {
      own = x;
    } else if (S.orientation_may_flip(ff.a, ff.b)) {
      own = Separation<Q>{Q(-x.num), x.norm2};
    } else {
      return fail("its edge axis is flipped outside the band (8)");
    }
  } else if (ff.type == FeatureType::EdgePair) {
    const EdgeGaps g = exact_edge_gaps(E, ff.a, ff.b);
    for (const bool plus : {true, false}) {
      const Separation<Q> v = plus ? g.plus() : g.minus();
      if (within(sf, v, bf) &&
          (exactly_supported(E, g, ff, plus) || S.support_may_accept(ff.a, ff.b, plus, g))) {
        own = v;
        break;
      }
    }
    if (!own)
      return fail("no orientation of its edge pair is within its support band (9) and its value bound");
  } else {
    own = exact_value(E, sat, ff);
  }
  if (!within(sf, *own, bf)) return fail("its value is outside its bound of its feature's exact value");
  if (classify_overlap(r.overlap, sign(*own) <= 0, *own, bf, false) == Classification::unexplained)
    return fail("its overlap verdict is not the one its feature's value implies");
  // (ii) and (iii), candidate by candidate
  std::string bad;
  auto measured = [&](const Separation<Q>& v, const Feature& f) {
    if (!bad.empty() || !beats(v, *own, bf + S.bound(sat, f))) return;
    bad =
        "it measured " + to_string(f) + " at exact value " + num(sepax::to_double(v)) + ", beyond its choice";
  };
  for (int f = 0; f < E.A.face_count(); ++f)
    measured(E.fqA[static_cast<std::size_t>(f)].separation,
             Feature::face_a(f, E.fqA[static_cast<std::size_t>(f)].support_vertex));
  for (int f = 0; f < E.B.face_count(); ++f)
    measured(E.fqB[static_cast<std::size_t>(f)].separation,
             Feature::face_b(E.fqB[static_cast<std::size_t>(f)].support_vertex, f));
  if (E.A.is_flat() && E.B.is_flat()) {  // side axes (best_axis.hpp): always measured
    for (int e = 0; e < E.A.edge_count(); ++e) {
      const auto q = E.k->side_query_a(e);
      measured(q.separation, Feature::side_a(e, q.support_vertex));
    }
    for (int e = 0; e < E.B.edge_count(); ++e) {
      const auto q = E.k->side_query_b(e);
      measured(q.separation, Feature::side_b(q.support_vertex, e));
    }
  }
  const int EB = E.B.edge_count();
  for (int ea = 0; ea < E.A.edge_count() && bad.empty(); ++ea)
    for (int eb = 0; eb < EB && bad.empty(); ++eb) {
      const Feature f = Feature::edges(ea, eb);
      const bool exact_candidate = E.minkowski_axis(ea, eb) != nullptr;  // Minkowski face, not parallel
      const bool skipped = k.edges_parallel(ea, eb);
      const bool taken =
          !skipped && (brute ? k.edge_separation_full(ea, eb).has_value() : k.minkowski_face(ea, eb));
      if (taken && brute) {
        const EdgeGaps g = exact_edge_gaps(E, ea, eb);  // the lower of the two orientations it may have taken
        measured(sepax::compare(g.plus(), g.minus()) <= 0 ? g.plus() : g.minus(), f);
      } else if (taken) {
        if (sat == Sat::traversal && !E.convex && (arc_prunable(S, ea, sf) || rest_prunable(S, k, ea, sf)))
          continue;  // (10)
        measured(value_as_decided(k, E, f), f);
      } else if (exact_candidate) {
        const Separation<Q> x = exact_value(E, sat, f);
        if (!beats(x, *own, bf + S.bound(sat, f))) continue;  // does not beat it
        if (skipped && parallel_band<F>(A.edge_direction(ea), B.edge_direction(eb)) == ParallelBand::inside)
          continue;                        // (6)
        if (!skipped && !brute) continue;  // its arc test: classified per pair (2)
        if (!skipped) {                    // the exact brute force measures only exactly supported pairs
          const EdgeGaps g = exact_edge_gaps(E, ea, eb);
          if (!exactly_supported(E, g, f, true) && !exactly_supported(E, g, f, false)) continue;
        }
        bad = "it did not measure " + to_string(f) + " (exact value " + num(sepax::to_double(x)) + ")" +
              (skipped ? " as parallel, outside the band (6)" : ", rejected by its support check");
      }
    }
  if (!bad.empty()) return fail(bad);
  d.ok = true;
  return d;
}

// Is a plain run's value sf of feature f within its bound bf of the exact
// value of f as the plain kernel may have decided it: xf, or for a Gauss-map
// or traversal edge pair the flipped orientation when the flip is within the
// band (8), or for a brute-force edge pair either orientation's gap (9)?
template <class F>
bool plain_value_within(const FloatSide<F>& S, Sat sat, const Feature& f, double sf, const Separation<Q>& xf,
                        double bf) {
  if (within(sf, xf, bf)) return true;
  if (f.type != FeatureType::EdgePair) return false;
  if (sat == Sat::brute_force) {
    const EdgeGaps g = exact_edge_gaps(S.E, f.a, f.b);
    return within(sf, g.plus(), bf) || within(sf, g.minus(), bf);
  }
  return S.orientation_may_flip(f.a, f.b) && within(sf, Separation<Q>{Q(-xf.num), xf.norm2}, bf);
}

// The speculative margin (SatOptions::margin with early_out), against the
// full result r of the same configuration and SAT and the exact answer R:
//   * no early exit: the result is the full result, bit for bit;
//   * an early exit: not overlapping, and the reported feature's separation is
//     beyond the margin (robust: exactly; plain: the float value, and its
//     exact value within its bound of it);
//   * robust: it exits early exactly when the exact maximum separation is
//     greater than the margin (decided in rationals); plain: when it does not
//     agree with that, the full result's own value is not beyond the margin
//     or the exact maximum is within the bounds of the margin (explained),
//     or the difference is unexplained.
// Margins: 0, half and twice the exact separation (when positive), and 2 % of
// the shapes' extent (an engine's speculative margin).
template <class F, class Policy, class Cls>
void check_margins(const FloatSide<F>& S, Sat sat, const SatResult<F>& full, const SatResult<Q>& R,
                   const std::string& cfg, bool exact_decisions, const Cls& cls, Recorder& rec) {
  const double se_d = std::max(0.0, sepax::to_double(R.separation));
  double extent = 0;
  for (const auto* p : {&S.A, &S.B})
    for (const auto& v : p->vertices())
      for (int c = 0; c < 3; ++c) extent = std::max(extent, std::abs(double(v[c])));
  const double margins[4] = {0.0, 0.02 * extent, 0.5 * se_d, 2 * se_d};
  const double be = S.bound(sat, R.feature);
  for (int i = 0; i < 4; ++i) {
    const double m = margins[i];
    if (!std::isfinite(m) || (i >= 2 && se_d == 0)) continue;
    SatOptions o;
    o.early_out = true;
    o.margin = m;
    const SatResult<F> r = run_sat<Policy>(sat, S.A, S.B, o);
    const Q qm(m);
    const bool exact_beyond = cmp_rational_sep(qm, R.separation) < 0;  // exact max separation > m
    Classification k = Classification::agree;
    std::string why;
    if (!r.early_out) {
      if (!same_bits(r, full)) {
        k = Classification::unexplained;
        why = "without an early exit the result is not the full result";
      } else if (exact_beyond) {
        // it found no axis beyond the margin, exact arithmetic has one.
        // Plain: explained when the full result's own value is not beyond
        // the margin either (the margin run did what its full run implies;
        // how that full result differs from the exact one is classified by
        // the feature and separation comparisons, e.g. a winning pair inside
        // the parallel-edge skip), or when the exact maximum is within the
        // bounds of the margin.
        k = exact_decisions ? Classification::unexplained
            : !(full.separation_as_double() > m) ||
                    close(R.separation, Separation<Q>{qm, Q(1)}, S.bound(sat, full.feature) + be)
                ? Classification::explained
                : Classification::unexplained;
        why = "no early exit, but the exact maximum separation is beyond the margin";
      }
    } else {
      const Separation<Q> xf = exact_value(S.E, sat, r.feature);
      const double bf = S.bound(sat, r.feature);
      const bool exact_feature_beyond = cmp_rational_sep(qm, xf) < 0;
      if (r.overlap) {
        k = Classification::unexplained;
        why = "an early exit that reports overlap";
      } else if (exact_decisions) {
        if (!exact_feature_beyond || !exact_beyond) {
          k = Classification::unexplained;
          why = "an early exit at a feature whose exact separation is not beyond the margin";
        }
      } else if (!(r.separation_as_double() > m)) {
        k = Classification::unexplained;
        why = "an early exit whose float separation is not beyond the margin";
      } else if (r.feature == full.feature && same_bits(r.separation, full.separation)) {
        // the full result's feature and value: classified by the feature and
        // separation comparisons (its own decisions included)
      } else if (!plain_value_within(S, sat, r.feature, r.separation_as_double(), xf, bf)) {
        k = Classification::unexplained;
        why = "an early exit whose float separation is not within its bound of its feature's exact value";
      } else if (!exact_feature_beyond) {
        k = Classification::explained;  // the float value is beyond, the exact one within its bound of it
      }
    }
    rec.add("margin", cfg, sat_name(sat), cls(k), [&] {
      std::ostringstream s;
      s << why << ": " << cfg << " " << sat_name(sat) << " margin " << num(m) << " early_out=" << r.early_out
        << " overlap=" << r.overlap << " feature " << to_string(r.feature) << " separation "
        << num(r.separation_as_double()) << "; full result: feature " << to_string(full.feature)
        << " separation " << num(full.separation_as_double()) << "; exact maximum "
        << num(sepax::to_double(R.separation));
      return s.str();
    });
  }
}

// gauss_out: this configuration's Gauss-map result, for the manifold check
// (the same query: run once, shared).
template <class F, class Policy>
void check_float(const Exact& E, const ConvexPolyhedron<F>& A, const ConvexPolyhedron<F>& B,
                 const std::string& cfg, bool exact_decisions, const CheckOptions& opt, Recorder& rec,
                 std::optional<SatResult<F>>& gauss_out) {
  const FloatSide<F> S(A, B, E);
  const int EA = A.edge_count(), EB = B.edge_count();
  // ---- arc signs and Minkowski-face verdicts, every edge pair ----
  {
    kernel_t<Policy, F> k(A, B);
    std::int64_t agree_signs = 0, agree_verdicts = 0, agree_sides = 0;
    for (int ea = 0; ea < EA; ++ea) {
      for (int eb = 0; eb < EB; ++eb) {
        const ArcSigns fs = k.arc_signs(ea, eb);
        const ArcSigns& es = E.arcs[E.pair_index(ea, eb)];
        const int f4[4] = {fs.cba, fs.dba, fs.adc, fs.bdc};
        const int e4[4] = {es.cba, es.dba, es.adc, es.bdc};
        Classification worst = Classification::agree;
        for (int i = 0; i < 4; ++i) {
          if (f4[i] == e4[i]) {
            ++agree_signs;
            continue;
          }
          // which normal and which edge direction
          const bool b_normal = i < 2;
          const int side = i % 2;
          const int face = b_normal ? B.edge_face(eb, side) : A.edge_face(ea, side);
          const Vec3<Q> Ne = b_normal ? E.B.plane(face).normal : E.A.plane(face).normal;
          const Vec3<Q> de = b_normal ? E.A.edge_direction(ea) : E.B.edge_direction(eb);
          const Q te = dot(Ne, de);
          const Vec3<F> nf = b_normal ? B.plane(face).normal : A.plane(face).normal;
          const Vec3<F> df = b_normal ? A.edge_direction(ea) : B.edge_direction(eb);
          const double bnd =
              bounds::arc_bound<F>(nf, df, (b_normal ? S.deltaB : S.deltaA)[static_cast<std::size_t>(face)]);
          // adc and bdc are negated dot products (sat_kernel.hpp)
          const Q signed_te = b_normal ? te : Q(-te);
          const Classification k2 =
              classify_sign(f4[i], Separation<Q>{signed_te, squared_norm(Ne)}, bnd, exact_decisions);
          worst = std::max(worst, k2);
          rec.add("arc_sign", cfg, "kernel", k2, [&] {
            std::ostringstream s;
            s << "edge pair (" << ea << "," << eb << ") " << side_name(i) << ": " << cfg << " sign " << f4[i]
              << " (value " << num((b_normal ? 1.0 : -1.0) * double(dot(nf, df))) << "), exact sign " << e4[i]
              << " (value " << num(signed_te.get_d() / std::sqrt(squared_norm(Ne).get_d()))
              << "), forward error bound " << num(bnd);
            return s.str();
          });
        }
        if (fs.minkowski_face() == es.minkowski_face()) {
          ++agree_verdicts;
        } else {
          if (worst == Classification::agree)
            worst = Classification::unexplained;  // cannot happen: verdict is a function of the signs
          rec.add("minkowski_face", cfg, "kernel", worst, [&] {
            std::ostringstream s;
            s << "edge pair (" << ea << "," << eb << "): " << cfg << " says "
              << (fs.minkowski_face() ? "Minkowski face" : "not a Minkowski face") << ", exact says "
              << (es.minkowski_face() ? "Minkowski face" : "not a Minkowski face");
            return s.str();
          });
        }
        // the orientation of the Gauss-map edge axis (sat_kernel.hpp
        // edge_separation), for every pair both sides measure
        if (!fs.minkowski_face()) continue;
        const Vec3<Q>* exact_axis = E.minkowski_axis(ea, eb);  // es a Minkowski face, not exactly parallel
        if (exact_axis == nullptr || k.edges_parallel(ea, eb)) continue;
        const Feature fpair = Feature::edges(ea, eb);
        const bool flipped = sgn(dot(vec_cast<Q>(k.axis(fpair)), *exact_axis)) <= 0;
        if (!flipped) {
          ++agree_sides;
          continue;
        }
        const Classification ks = exact_decisions                  ? Classification::unexplained
                                  : S.orientation_may_flip(ea, eb) ? Classification::explained
                                                                   : Classification::unexplained;
        rec.add("axis_side", cfg, "kernel", ks, [&] {
          std::ostringstream s;
          s << "edge pair (" << ea << "," << eb << "): " << cfg
            << " orients the edge axis the other way from exact arithmetic"
            << (ks == Classification::explained ? ", within the bound (8)" : ", outside the bound (8)");
          return s.str();
        });
      }
    }
    rec.add("arc_sign", cfg, "kernel", Classification::agree, nullptr, agree_signs);
    rec.add("minkowski_face", cfg, "kernel", Classification::agree, nullptr, agree_verdicts);
    rec.add("axis_side", cfg, "kernel", Classification::agree, nullptr, agree_sides);
  }
  // ---- every SAT ----
  for (Sat sat : all_sats()) {
    if (sat == Sat::brute_force && static_cast<double>(EA) * EB * (A.vertex_count() + B.vertex_count()) >
                                       static_cast<double>(opt.float_brute_budget)) {
      for (const char* cmp : {"overlap", "feature", "separation"}) rec.skip(cmp, cfg, sat_name(sat));
      continue;
    }
    // The exact answer of this SAT (the mpq Gauss map when the input is
    // exactly convex, where all exact SATs agree; otherwise mpq's run of the
    // same SAT when it was made).  Only a comparison that still crosses SATs
    // on a non-convex input may be classified nonconvex.
    const SatResult<Q>& R = E.ref_for(sat);
    const Feature& fe = R.feature;
    const Separation<Q>& se = R.separation;
    const bool crosses = E.cross_sat(sat);
    auto cls = [crosses](Classification k) {
      return (crosses && k == Classification::unexplained) ? Classification::nonconvex : k;
    };
    SatResult<F> r = run_sat<Policy>(sat, A, B);
    if (opt.inject_fault && exact_decisions && sat == Sat::gauss_map && std::is_same_v<F, float>)
      r.overlap = !r.overlap;  // CheckOptions::inject_fault
    if (sat == Sat::gauss_map) gauss_out = r;
    rec.rep.configs_run.push_back(cfg + "/" + sat_name(sat));
    const Feature& ff = r.feature;
    const double sf = r.separation_as_double();
    const double bf = S.bound(sat, ff), be = S.bound(sat, fe);
    const Separation<Q> xf = exact_value(E, sat, ff);
    // The usual rules first: the float measured what exact arithmetic
    // measured, every value within its bound.
    Classification ko = classify_overlap(r.overlap, R.overlap, se, bf + be, exact_decisions);
    Classification kf = Classification::agree;
    if (!(ff == fe)) {
      if (exact_decisions) {
        kf = Classification::unexplained;
      } else if (same_axis(ff, fe) && (ff.type == FeatureType::SideA || ff.type == FeatureType::SideB)) {
        // same side axis, different support vertex: their exact heights
        const bool on_a = ff.type == FeatureType::SideA;
        const int e = on_a ? ff.a : ff.b;
        const CPQ& p = on_a ? E.A : E.B;
        const CPQ& q = on_a ? E.B : E.A;
        const Separation<Q> h1 = exact_side_height(p, e, q, on_a ? ff.b : ff.a);
        const Separation<Q> h2 = exact_side_height(p, e, q, on_a ? fe.b : fe.a);
        kf = close(h1, h2, 2 * bf) ? Classification::tie : Classification::unexplained;
      } else if (same_axis(ff, fe)) {
        // same face, different support vertex: compare the two vertices' exact heights
        const bool on_a = ff.type == FeatureType::FaceA;
        const Separation<Q> h1 =
            on_a ? E.k->face_separation_a(ff.a, ff.b) : E.k->face_separation_b(ff.b, ff.a);
        const Separation<Q> h2 =
            on_a ? E.k->face_separation_a(fe.a, fe.b) : E.k->face_separation_b(fe.b, fe.a);
        kf = close(h1, h2, 2 * bf) ? Classification::tie : Classification::unexplained;
      } else {
        kf = close(xf, se, bf + be) ? Classification::tie : Classification::unexplained;
      }
    }
    Classification ks = classify_separation(sf, se, same_axis(ff, fe), bf, be, exact_decisions);
    // Then, for a plain run, its kernel's own decisions (decision_check): a
    // difference that follows from decisions each within its band is explained.
    // When its kernel did not measure the exact winner as exact arithmetic
    // does (skipped it as parallel, or flipped its axis), the rules above do
    // not apply at all (a "tie" would rest on a value it never computed): every
    // difference is then explained by its decisions or unexplained.
    bool winner_unmeasured = false;
    if (!exact_decisions && !(ff == fe) && fe.type == FeatureType::EdgePair) {
      const kernel_t<Policy, F> k(A, B);
      winner_unmeasured =
          k.edges_parallel(fe.a, fe.b) || (sat != Sat::brute_force && orientation_flipped(k, E, fe));
    }
    std::optional<DecisionCheck> dc;
    if (!exact_decisions && (winner_unmeasured || ko == Classification::unexplained ||
                             kf == Classification::unexplained || ks == Classification::unexplained)) {
      dc = decision_check<F, Policy>(S, sat, r, bf);
      const Classification by_decisions = dc->ok ? Classification::explained : Classification::unexplained;
      for (Classification* k : {&ko, &kf, &ks})
        if (*k == Classification::unexplained || (winner_unmeasured && *k != Classification::agree))
          *k = by_decisions;
    }
    auto describe = [&](const char* what) {
      return [&, what] {
        std::ostringstream s;
        s << what << ": " << cfg << " " << sat_name(sat) << " reports overlap=" << r.overlap << " feature "
          << to_string(ff) << " separation " << num(sf) << " (exact value of that feature "
          << num(sepax::to_double(xf)) << ", bound " << num(bf) << "); exact: overlap=" << R.overlap
          << " feature " << to_string(fe) << " separation " << num(sepax::to_double(se)) << " (" << cfg
          << " bound for it " << num(be) << ")";
        if (dc && !dc->ok) s << "; " << cfg << "'s own decisions do not explain it: " << dc->why;
        return s.str();
      };
    };
    rec.add("overlap", cfg, sat_name(sat), cls(ko), describe("overlap verdict differs"));
    rec.add("feature", cfg, sat_name(sat), cls(kf), describe("feature differs"));
    rec.add("separation", cfg, sat_name(sat), cls(ks), describe("separation outside its bound"));
    if (opt.margins) check_margins<F, Policy>(S, sat, r, R, cfg, exact_decisions, cls, rec);
  }
}

// given_a, given_b: the case's images in T when check_case has converted
// them already (ConvexPolyhedron<T>::convert_from of Af, Bf), else null.
template <class T>
void check_exact_type(const ConvexPolyhedron<float>& Af, const ConvexPolyhedron<float>& Bf, Exact& E,
                      const std::string& cfg, bool skip_reference, const CheckOptions& opt, Recorder& rec,
                      std::optional<SatResult<T>>* gauss_out = nullptr,
                      const ConvexPolyhedron<T>* given_a = nullptr,
                      const ConvexPolyhedron<T>* given_b = nullptr) {
  // mpq: the reference's own exact images E.A, E.B (the same conversion)
  std::optional<ConvexPolyhedron<T>> own_a, own_b;
  const ConvexPolyhedron<T>* pa = nullptr;
  const ConvexPolyhedron<T>* pb = nullptr;
  if constexpr (std::is_same_v<T, Q>) {
    pa = &E.A;
    pb = &E.B;
  } else if (given_a != nullptr && given_b != nullptr) {
    pa = given_a;
    pb = given_b;
  } else {
    pa = &own_a.emplace(ConvexPolyhedron<T>::convert_from(Af));
    pb = &own_b.emplace(ConvexPolyhedron<T>::convert_from(Bf));
  }
  const ConvexPolyhedron<T>& A = *pa;
  const ConvexPolyhedron<T>& B = *pb;
  const double cost =
      static_cast<double>(A.edge_count()) * B.edge_count() * (A.vertex_count() + B.vertex_count());
  for (Sat sat : all_sats()) {
    if (skip_reference && sat == Sat::gauss_map) continue;  // it is the reference itself
    if ((sat == Sat::brute_force && cost > static_cast<double>(opt.exact_brute_budget)) ||
        (sat == Sat::gauss_map && static_cast<double>(A.edge_count()) * B.edge_count() >
                                      static_cast<double>(opt.exact_gauss_pair_budget))) {
      rec.skip("exact", cfg, sat_name(sat));
      continue;
    }
    const SatResult<T> r = run_sat<policy::Plain>(sat, A, B);
    if (gauss_out && sat == Sat::gauss_map) *gauss_out = r;
    rec.rep.configs_run.push_back(cfg + "/" + sat_name(sat));
    // mpq: always against the reference (mpq Gauss map); other exact types:
    // against mpq's run of the same SAT when the input is not exactly convex.
    const bool is_mpq = std::is_same_v<T, Q>;
    const SatResult<Q>& R = is_mpq ? E.ref : E.ref_for(sat);
    const bool crosses = sat != Sat::gauss_map && (is_mpq || E.cross_sat(sat));
    bool same = r.overlap == R.overlap && r.feature == R.feature;
    if constexpr (std::is_same_v<T, Q>) {
      same = same && sepax::compare(r.separation, R.separation) == 0;
      if (!E.convex) E.ref_by_sat[static_cast<std::size_t>(sat)] = r;
    }
    const Classification k = same                     ? Classification::agree
                             : (!E.convex && crosses) ? Classification::nonconvex
                                                      : Classification::unexplained;
    rec.add("exact", cfg, sat_name(sat), k, [&] {
      std::ostringstream s;
      s << cfg << " " << sat_name(sat) << ": overlap=" << r.overlap << " feature " << to_string(r.feature)
        << " separation " << num(sepax::to_double(r.separation)) << "; reference mpq "
        << (&R == &E.ref ? "gauss_map" : sat_name(sat)) << ": overlap=" << R.overlap << " feature "
        << to_string(R.feature) << " separation " << num(sepax::to_double(R.separation))
        << (E.convex ? "" : " (exact image not exactly convex)");
      return s.str();
    });
  }
}

}  // namespace

namespace {

using Z = mpz_class;
using VZ = std::array<Z, 3>;

// Both shapes scaled by a common power of two 2^S to integers: every float is
// an integer times 2^-S for a common S, so the scaling is exact, and every sign
// below (of n.d, or of the difference of two heights n.v) is the sign of the
// same rational expression times a positive power of two.  The integers need
// no normalisation (gcds) -- the exact reference is the cost of the fuzzer.
//   n   face normals (t1 - t0) x (t2 - t0) of the plane triples: positive
//       multiples of ConvexPolyhedron<mpq>'s plane normals (a flat shape's
//       back face has the reversed triple, as its plane is the front negated);
//   d   edge directions head - tail.
struct IntegerImages {
  std::vector<VZ> va, vb, na, nb, da, db;

  IntegerImages(const ConvexPolyhedron<float>& A, const ConvexPolyhedron<float>& B) {
    int S = 0;
    for (const auto* p : {&A, &B})
      for (const auto& v : p->vertices())
        for (int c = 0; c < 3; ++c)
          if (v[c] != 0.0f) {
            int e;
            std::frexp(double(v[c]), &e);
            S = std::max(S, 24 - e);
          }
    auto to_z = [&](const ConvexPolyhedron<float>& p) {
      std::vector<VZ> out;
      for (const auto& v : p.vertices())
        out.push_back(
            {Z(std::ldexp(double(v[0]), S)), Z(std::ldexp(double(v[1]), S)), Z(std::ldexp(double(v[2]), S))});
      return out;
    };
    auto normals = [&](const ConvexPolyhedron<float>& p, const std::vector<VZ>& v) {
      std::vector<VZ> out;
      for (int f = 0; f < p.face_count(); ++f) {
        const auto& t = p.face(f).plane_vertices;
        out.push_back(crs(sub(v[static_cast<std::size_t>(t[1])], v[static_cast<std::size_t>(t[0])]),
                          sub(v[static_cast<std::size_t>(t[2])], v[static_cast<std::size_t>(t[0])])));
      }
      return out;
    };
    auto dirs = [&](const ConvexPolyhedron<float>& p, const std::vector<VZ>& v) {
      std::vector<VZ> out;
      for (int e = 0; e < p.edge_count(); ++e)
        out.push_back(
            sub(v[static_cast<std::size_t>(p.edge_head(e))], v[static_cast<std::size_t>(p.edge_tail(e))]));
      return out;
    };
    va = to_z(A);
    vb = to_z(B);
    na = normals(A, va);
    nb = normals(B, vb);
    da = dirs(A, va);
    db = dirs(B, vb);
  }

  static VZ sub(const VZ& a, const VZ& b) { return VZ{Z(a[0] - b[0]), Z(a[1] - b[1]), Z(a[2] - b[2])}; }
  static VZ crs(const VZ& a, const VZ& b) {
    return VZ{Z(a[1] * b[2] - a[2] * b[1]), Z(a[2] * b[0] - a[0] * b[2]), Z(a[0] * b[1] - a[1] * b[0])};
  }
  // acc = n . d
  static void dot_into(Z& acc, const VZ& n, const VZ& d) {
    mpz_mul(acc.get_mpz_t(), n[0].get_mpz_t(), d[0].get_mpz_t());
    mpz_addmul(acc.get_mpz_t(), n[1].get_mpz_t(), d[1].get_mpz_t());
    mpz_addmul(acc.get_mpz_t(), n[2].get_mpz_t(), d[2].get_mpz_t());
  }
};

// Face f of p (normals n) against the vertices v of the other shape: the
// lowest-index vertex of least n.v, the support vertex PlainKernel<mpq>'s
// face query picks (support_below: the first strict minimum of the same
// heights up to the positive factor 2^(3S)).
std::vector<int> face_supports(const std::vector<VZ>& n, const std::vector<VZ>& v) {
  std::vector<int> out;
  out.reserve(n.size());
  Z best, h;
  for (const VZ& nf : n) {
    int arg = 0;
    IntegerImages::dot_into(best, nf, v[0]);
    for (std::size_t i = 1; i < v.size(); ++i) {
      IntegerImages::dot_into(h, nf, v[i]);
      if (h < best) {
        mpz_swap(best.get_mpz_t(), h.get_mpz_t());
        arg = static_cast<int>(i);
      }
    }
    out.push_back(arg);
  }
  return out;
}

// The float coordinates (as doubles, exactly) of the plane triples of p's
// faces (t0, t1, t2: 9 per face) and of the endpoints of its edges (tail,
// head: 6 per edge), for the filter in arc_signs_of.
std::vector<double> triple_coordinates(const ConvexPolyhedron<float>& p) {
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(p.face_count()) * 9);
  for (int f = 0; f < p.face_count(); ++f)
    for (int v : p.face(f).plane_vertices)
      for (int c = 0; c < 3; ++c) out.push_back(double(p.vertex(v)[c]));
  return out;
}
std::vector<double> edge_coordinates(const ConvexPolyhedron<float>& p) {
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(p.edge_count()) * 6);
  for (int e = 0; e < p.edge_count(); ++e)
    for (int v : {p.edge_tail(e), p.edge_head(e)})
      for (int c = 0; c < 3; ++c) out.push_back(double(p.vertex(v)[c]));
  return out;
}

// Each sign is sign(n . d) for the normal n of a face of one shape and the
// direction d of an edge of the other.  The semi-static filter decides it
// first on the float coordinates: n . d = det[head - tail, t1 - t0, t2 - t0]
// (orientation_filter.hpp, whose every certain sign is the exact sign); the
// integers (IntegerImages: the same value times a positive power of two)
// decide the rest, an exact zero included (the filter is never certain of 0).
std::vector<ArcSigns> arc_signs_of(const ConvexPolyhedron<float>& A, const ConvexPolyhedron<float>& B,
                                   const IntegerImages& I) {
  Z acc;
  const std::vector<double> ta = triple_coordinates(A), tb = triple_coordinates(B);
  const std::vector<double> ea_xyz = edge_coordinates(A), eb_xyz = edge_coordinates(B);
  // sign(n_f . d_e): t the triple of face f (9 doubles), x the endpoints of
  // edge e (6 doubles), n and d their integer images
  auto dsign = [&](const double* t, const double* x, const VZ& n, const VZ& d) {
    const FilteredSign fs = orientation_filter(x[0], x[1], x[2], x[3], x[4], x[5], t[0], t[1], t[2], t[3],
                                               t[4], t[5], t[0], t[1], t[2], t[6], t[7], t[8]);
    if (fs.certain) return fs.det > 0 ? 1 : -1;
    IntegerImages::dot_into(acc, n, d);
    return mpz_sgn(acc.get_mpz_t());
  };
  std::vector<ArcSigns> out;
  out.reserve(static_cast<std::size_t>(A.edge_count()) * static_cast<std::size_t>(B.edge_count()));
  for (int ea = 0; ea < A.edge_count(); ++ea) {
    const int fa0 = A.edge_face(ea, 0), fa1 = A.edge_face(ea, 1);
    const VZ& a0 = I.na[static_cast<std::size_t>(fa0)];
    const VZ& a1 = I.na[static_cast<std::size_t>(fa1)];
    const double* ta0 = ta.data() + static_cast<std::size_t>(fa0) * 9;
    const double* ta1 = ta.data() + static_cast<std::size_t>(fa1) * 9;
    const double* xa = ea_xyz.data() + static_cast<std::size_t>(ea) * 6;
    const VZ& da = I.da[static_cast<std::size_t>(ea)];
    for (int eb = 0; eb < B.edge_count(); ++eb) {
      const int fb0 = B.edge_face(eb, 0), fb1 = B.edge_face(eb, 1);
      const double* xb = eb_xyz.data() + static_cast<std::size_t>(eb) * 6;
      const VZ& db = I.db[static_cast<std::size_t>(eb)];
      ArcSigns s;
      s.cba =
          dsign(tb.data() + static_cast<std::size_t>(fb0) * 9, xa, I.nb[static_cast<std::size_t>(fb0)], da);
      s.dba =
          dsign(tb.data() + static_cast<std::size_t>(fb1) * 9, xa, I.nb[static_cast<std::size_t>(fb1)], da);
      s.adc = -dsign(ta0, xb, a0, db);
      s.bdc = -dsign(ta1, xb, a1, db);
      out.push_back(s);
    }
  }
  return out;
}

}  // namespace

std::vector<ArcSigns> exact_arc_signs(const ConvexPolyhedron<float>& A, const ConvexPolyhedron<float>& B) {
  // the signs PlainKernel<mpq>::arc_signs computes, in integers (IntegerImages)
  return arc_signs_of(A, B, IntegerImages(A, B));
}

std::vector<int> exact_face_supports(const ConvexPolyhedron<float>& A, const ConvexPolyhedron<float>& B) {
  const IntegerImages I(A, B);
  return face_supports(I.na, I.vb);
}

CaseReport check_case(const FuzzCase& c, const CheckOptions& opt) {
  CaseReport rep;
  ConvexPolyhedron<float> Af, Bf;
  // (a finite coordinate beyond float's range is named as such, not as the infinity it rounds to)
  auto build = [](const ShapeSpec& s) {
    std::vector<Vec3<float>> v;
    for (const auto& p : s.vertices) {
      v.emplace_back(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
      for (int k = 0; k < 3; ++k)
        if (std::isfinite(p[k]) && !std::isfinite(v.back()[k]))
          throw coordinate_beyond_range(k, "vertex", v.size() - 1, p[k], "float");
    }
    return ConvexPolyhedron<float>::from_faces(std::move(v), s.faces);
  };
  try {
    Af = build(c.a);
  } catch (const InvalidInput& e) {
    rep.reject_reason = std::string("shape A: ") + e.what();
    return rep;
  }
  try {
    Bf = build(c.b);
  } catch (const InvalidInput& e) {
    rep.reject_reason = std::string("shape B: ") + e.what();
    return rep;
  }
  rep.valid = true;
  Recorder rec{rep, opt, {}};

  // exact reference
  Exact E;
  E.A = CPQ::convert_from(Af);
  E.B = CPQ::convert_from(Bf);
  E.k = std::make_unique<PlainKernel<Q>>(E.A, E.B);
  // The face queries E.k->face_query_a/b(f) would give: the support vertex
  // decided in integers (face_supports), its height in rationals.
  const IntegerImages I(Af, Bf);
  const std::vector<int> supA = face_supports(I.na, I.vb), supB = face_supports(I.nb, I.va);
  for (int f = 0; f < E.A.face_count(); ++f) {
    const int v = supA[static_cast<std::size_t>(f)];
    E.fqA.push_back(FaceQuery<Q>{E.k->face_separation_a(f, v), v});
    E.nlenA.push_back(bounds::sqrt_lower(squared_norm(E.A.plane(f).normal).get_d()));
  }
  for (int f = 0; f < E.B.face_count(); ++f) {
    const int v = supB[static_cast<std::size_t>(f)];
    E.fqB.push_back(FaceQuery<Q>{E.k->face_separation_b(f, v), v});
    E.nlenB.push_back(bounds::sqrt_lower(squared_norm(E.B.plane(f).normal).get_d()));
  }
  E.arcs = arc_signs_of(Af, Bf, I);
  E.fill_minkowski_axes();
  {
    ReferenceKernel rk(E);
    E.ref = sat::gauss_map_with(rk);
  }
  E.convex = exactly_convex(Af) && exactly_convex(Bf);
  rep.configs_run.push_back("mpq/gauss_map");

  // exact types among themselves
  check_exact_type<Q>(Af, Bf, E, "mpq", true, opt, rec);
  // Each configuration's Gauss-map result and the images it was computed on,
  // converted once here and shared with the manifold and posed checks.
  CaseGaussMaps gauss;
  std::optional<ConvexPolyhedron<CGAL::Gmpq>> Ag, Bg;
  if (static_cast<std::int64_t>(E.A.edge_count()) * E.B.edge_count() <= opt.gmpq_pair_budget) {
    Ag.emplace(ConvexPolyhedron<CGAL::Gmpq>::convert_from(Af));
    Bg.emplace(ConvexPolyhedron<CGAL::Gmpq>::convert_from(Bf));
    gauss.gmpq_a = &*Ag;
    gauss.gmpq_b = &*Bg;
    check_exact_type<CGAL::Gmpq>(Af, Bf, E, "gmpq", false, opt, rec, &gauss.gmpq, &*Ag, &*Bg);
  } else {
    for (Sat sat : all_sats()) rec.skip("exact", "gmpq", sat_name(sat));
  }
  check_exact_type<CGAL::Epeck::FT>(Af, Bf, E, "epeck", false, opt, rec);

  // float configurations on identical inputs
  const auto Ad = ConvexPolyhedron<double>::convert_from(Af);
  const auto Bd = ConvexPolyhedron<double>::convert_from(Bf);
  gauss.double_a = &Ad;
  gauss.double_b = &Bd;
  check_float<float, policy::Plain>(E, Af, Bf, "float_plain", false, opt, rec, gauss.float_plain);
  check_float<double, policy::Plain>(E, Ad, Bd, "double_plain", false, opt, rec, gauss.double_plain);
#if SEPAX_FUZZ_HAS_ROBUST
  check_float<float, policy::Robust>(E, Af, Bf, "float_robust", true, opt, rec, gauss.float_robust);
  check_float<double, policy::Robust>(E, Ad, Bd, "double_robust", true, opt, rec, gauss.double_robust);
#endif
  if (opt.manifolds) check_manifolds(Af, Bf, E.A, E.B, E.ref, gauss, opt, rep);
  if (opt.posed) check_posed(Af, Bf, Ad, Bd, E.A, E.B, c.seed, opt, rep);
  return rep;
}

CaseReport check_case_guarded(const FuzzCase& c, const CheckOptions& opt) {
  try {
    return check_case(c, opt);
  } catch (const std::exception& e) {
    // A library component threw on valid input (InvalidInput is caught inside
    // check_case as a rejection): a finding like an unexplained disagreement.
    CaseReport r;
    r.valid = true;
    r.by_comparison["internal_error"].add(Classification::unexplained);
    r.by_config["internal_error/-"].add(Classification::unexplained);
    r.unexplained.push_back({"internal_error", "-", "-", std::string("exception: ") + e.what()});
    r.unexplained_count = 1;
    return r;
  }
}

}  // namespace sepax::fuzz
