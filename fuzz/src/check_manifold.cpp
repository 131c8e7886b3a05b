// The contact-manifold comparison of the checking core: see
// sepax/fuzz/check_manifold.hpp for what is compared and the classes.
//
// ===================== Forward error bounds (derivation) =====================
//
// Notation as in error_bounds.hpp: F = float or double, u its unit roundoff,
// g_k = k u / (1 - k u).  Every input coordinate is an exact F value; the
// exact manifold is contact_manifold on the exact images (mpq).  Every step is
// charged for separate roundings of each operation, so the bounds hold with
// and without FMA contraction (an FMA rounds once where these charge twice).
// "Exact counterpart" of a float quantity = the same construction (same
// features, same operations) done in exact arithmetic on the exact inputs; when
// the float and exact manifolds have the same ids it is the exact manifold's
// value.  Exact normals are unnormalised in mpq; every exact height below is
// taken with the unit normal n_e = N_e/|N_e| (intersection points and signs do
// not depend on that scale).
//
// (M1) Reference normal n (the float face plane's unit normal) and offset
//      o = fl(n.p0), p0 the first point of the plane triple:
//        ||n - n_e|| <= dn   (error_bounds.hpp (1), delta_normal).
//
// (M2) Side plane of reference edge t->h:  e = fl(v_h - v_t), c = fl(e x n),
//      oc = fl(c.v_t);  exact  c_e = (v_h - v_t) x n_e.
//        ||e - e_e|| <= g1 ||e||  (one rounding per component),
//        fl(e x n) - e x n          <= g2 |e| x |n|       (componentwise),
//        (e - e_e) x n              <= g1 ||e|| ||n||,
//        e_e x (n - n_e)            <= (1 + g1) ||e|| dn:
//     => ||c - c_e|| <= dc = g2 || |e| x |n| || + g1 ||e|| ||n|| + (1 + g1) ||e|| dn.
//
// (M3) Height of a clip vertex p (float, ||p - p_e|| <= ep) on that plane:
//      h = fl(fl(c.p) - oc);  exact h_e = c_e.(p_e - v_t).
//        |fl(c.p) - c.p| <= g3 sum|c_i||p_i|,  |oc - c.v_t| <= g3 sum|c_i||v_t,i|,
//        the subtraction: <= g1 |h|,
//        |c.(p - v_t) - c_e.(p_e - v_t)| <= dc ||p - v_t|| + (||c|| + dc) ep:
//     => eh(p) = g3 (sum|c||p| + sum|c||v_t|) + g1 |h| + dc ||p - v_t|| + (||c|| + dc) ep.
//
// (M4) Intersection (clip_polygon's cut) of segment a -> b (heights h_a, h_b
//      of strictly opposite signs, bounds ea = eh(a), eb = eh(b); position
//      bounds pa, pb): D = fl(h_a - h_b), t = fl(h_a / D), p_i = fl(a_i +
//      fl(t fl(b_i - a_i))).  Exact t_e = h_ae / (h_ae - h_be), p_e = a_e +
//      t_e (b_e - a_e).
//        |t - h_a/(h_a - h_b)| <= g2 |t|                     (D and the division),
//        |h_a/D' - h_ae/D_e| <= (|h_a| (ea + eb) + |D'| ea) / (|D'| |D_e|)
//                            <= (2 ea + eb) / (|D'| - ea - eb)
//          with D' = h_a - h_b, |D'| = |h_a| + |h_b| >= |D| (1 - u), |h_a| <= |D'|,
//          |D_e| >= |D'| - ea - eb  (if that is <= 0 the bound is infinite: the
//          segment lies within its bound of the plane);
//        dt = g2 |t| + (2 ea + eb) / (|D|(1 - u) - ea - eb);
//        |p_i - (a_i + t (b_i - a_i))| <= g2 |t| |b_i - a_i| + g1 |p_i|;
//        (a + t (b - a)) - p_e = (1 - t)(a - a_e) + t (b - b_e) + (t - t_e)(b_e - a_e):
//     => ep = (1 - t) pa + t pb + dt ((1 + g1)||fl(b - a)|| + pa + pb)
//             + g2 t (1 + g1) ||fl(b - a)|| + g1 ||p||.
//      Error grows through the clip steps (an intersection point is clipped
//      again); the replay below propagates ep vertex by vertex.  The
//      1/|D| factor is the conditioning of a segment nearly parallel to a side
//      plane.
//
// (M5) Depth (separation) of a kept point p: s = fl(fl(n.p) - o); exact
//      s_e = n_e.(p_e - p0):
//     => es = g3 (sum|n||p| + sum|n||p0|) + g1 |s| + dn ||p - p0|| + (||n|| + dn) ep.
//
// (M6) Projection onto the reference plane, q_i = fl(p_i - fl(n_i s)) (norm2 = 1
//      for F, so the quotient s/norm2 is s); exact q_e = p_e - n_e s_e:
//        ||n s - n_e s_e|| <= dn |s| + es;  roundings <= g1 (||n|| |s| + ||q||):
//     => eq = ep + dn |s| + es + g1 (||n|| |s| + ||q||).
//      Position x = fl((p + q) * 1/2) (the halving is exact):
//     => ex = (ep + eq) / 2 + g1 ||x||.
//
// (M7) Edge contact (Ericson's clamped closest points of the edge segments,
//      contact_manifold.hpp).  Float vectors da = fl(hA - tA), db, r = fl(pA -
//      pB); X = ||da||, Y = ||db||, R = ||r||.  The rounding of the inputs
//      (<= g1 per component) and of each dot product (g3) together perturb
//      every dot product a = da.da, e, b = da.db, c = da.r, f = db.r by at most
//      g6 times the product of the norms (|a - A| <= g6 X^2, |b - B| <= g6 X Y,
//      |c - C| <= g6 X R, |f - F| <= g6 Y R; A.. exact, from the exact vectors).
//        den = fl(fl(a e) - fl(b b)):  |den - (AE - B^2)| <= dD = (g8 + 3 g6 + 2 g1) X^2 Y^2
//          (a e: g6 + g6 + one product rounding; b^2: |b^2 - B^2| <= |b - B|(|b| + |B|)
//           <= 3 g6 X^2 Y^2; the subtraction g1 |den| <= g1 (1 + g8) X^2 Y^2).
//        N = fl(fl(b f) - fl(c e)):  |N - (BF - CE)| <= dN = 6 g6 X Y^2 R + g1 |N|.
//        s_raw = fl(N / den):  |s_raw - s*| <= ds = (dN + |s_raw| dD) / (|den| - dD) + g1 |s_raw|
//          (infinite if |den| <= dD: edges parallel within the bound); clamping to
//          [0, 1] is 1-Lipschitz.
//        t = fl(fl(fl(b s) + f) / e):  t* = (B s* + F)/E:
//          |t - t*| <= dt = (g6 X Y |s| + X Y ds + g6 Y R + 2 g1 (|b s| + |b s + f|)) / (Y^2 (1 - g6))
//                          + (g6 + g1) |t|.
//        When t is clamped the float recomputes s = clamp(-c/a) or clamp((b - c)/a)
//        (the minimiser for t = 0 / 1); the exact run may have clamped
//        differently, but its t is within dt of the float's and s(t) = (B t -
//        C)/A moves by at most (Y/X) dt:  s2 error <= ds2 = (g6 X (R + Y) +
//        g1 (|b| + |c|)) / (X^2 (1 - g6)) + g1 |s|.
//     => |s - s_e| <= ds + ds2 + (Y/X) dt =: Ds,  |t - t_e| <= dt =: Dt, and
//        point_a = fl(pA + fl(s da)):  ||point_a - point_a_e|| <= X Ds + g1 |s| X + g2 (|s| X + ||point_a||),
//        the same for point_b with Y, Dt; position as in (M6).
//      Depth: the SAT separation, bounded by error_bounds.hpp (4).
//
// (M8) Reduction (manifold_reduction.hpp): the float reduction maximises its
//      float H within area_tol = kContactArea * extent^2 (and picks the deepest
//      within key_tol = kContactWeld * extent).  The H of a point set is at
//      most 2 max |T| terms; for T(a,b,c) = ((b - a) x (c - a)).n with x = b - a,
//      y = c - a:  |fl(T) - T| <= g7 (|x| x |y|).|n|, and against the exact
//      positions (bounds ea, eb, ec) and unit normal:
//        |T - T_e| <= ||n|| ((ea + eb) ||y|| + (||x|| + ea + eb)(ea + ec))
//                     + (||x|| + ea + eb)(||y|| + ea + ec) dn.
//      The deepest point d is chosen first (within key_tol of the smallest
//      key: its exact depth within key_tol + 2 es_max of the exact deepest's),
//      then H is maximised over the sets containing d.  With X_o the exact
//      optimum among the sets containing the float's d (the exact choice X_e
//      when both pick the same d), the float choice X_f satisfies
//      H_f(X_f) >= H_f(X_o) - area_tol, so
//      H_e(X_f) >= H_e(X_o) - area_tol - dH(X_f) - dH(X_o): a different choice
//      within that is a tie.  (Found by `sepax fuzz --seconds 600 --seed 12`:
//      a float d tied within key_tol with the exact one, whose best quad is
//      0.8% smaller than the exact optimum; corpus 36.)
//
// Every bound is evaluated in double and multiplied by kSlack (1 + 2^-30),
// far above the relative rounding of the ~100 double operations involved.
// Geometric tests on unmatched points (distances to polygons and planes) are
// classification, evaluated in double with a relative slack of 2^-40.
#include <sepax/fuzz/check_manifold.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <ostream>
#include <sstream>
#include <utility>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <sepax/clip_polygon.hpp>
#include <sepax/contact_manifold.hpp>
#include <sepax/fuzz/classify.hpp>
#include <sepax/fuzz/error_bounds.hpp>
#include <sepax/fuzz/sat_list.hpp>
#include <sepax/manifold_reduction.hpp>
#include <sepax/robust/number_types.hpp>

namespace sepax::fuzz {

namespace {

using Q = mpq_class;
using bounds::gamma;
using bounds::kSlack;
using V = Vec3<double>;
constexpr double kInf = std::numeric_limits<double>::infinity();

double nrm(const V& v) { return bounds::norm(v); }

std::string num(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.9g", x);
  return b;
}

Q to_q(const CGAL::Gmpq& x) { return Q(x.mpq()); }
template <class F>
Q to_q(F x) {
  return Q(static_cast<double>(x));
}
template <class T>
Vec3<Q> vq(const Vec3<T>& v) {
  return Vec3<Q>(to_q(v[0]), to_q(v[1]), to_q(v[2]));
}
template <class T>
V vd(const Vec3<T>& v) {
  return vec_to_double(v);
}

// Distance from x to the segment [a, b] (double; classification).
double seg_dist(const V& x, const V& a, const V& b) {
  const V ab = b - a;
  const double l2 = ab.squaredNorm();
  double t = l2 > 0 ? (x - a).dot(ab) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return (x - (a + t * ab)).norm();
}
// Distance from x to the boundary of the closed polygon `poly` (or its point).
double poly_dist(const V& x, const std::vector<V>& poly) {
  if (poly.empty()) return kInf;
  if (poly.size() == 1) return (x - poly[0]).norm();
  double d = kInf;
  for (std::size_t i = 0; i < poly.size(); ++i)
    d = std::min(d, seg_dist(x, poly[i], poly[(i + 1) % poly.size()]));
  return d;
}

// ---------------------------------------------------------------------------
// Clip replay: the clip of contact_manifold.hpp's face_contact, step by step,
// with the bounds (M2)-(M4) propagated for float T (ignored for exact T);
// welded as the library welds, squared lengths in units of 2^unit.
template <class T>
struct Replay {
  std::vector<ClipVertex<T>> poly;  // the clipped incident polygon (float: after the welds)
  std::vector<double> ep;           // float: position bound of each vertex (M4)
  std::vector<V> planes_n;          // float: unit side-plane normals and offsets (double), for distances
  std::vector<double> planes_o;
  double rho = 0;           // float: largest height bound of a decision, as a distance
  bool exact_zero = false;  // a vertex exactly on a side plane (exact T)
  bool infinite = false;    // some bound was infinite (ill-conditioned cut)
};

template <class T>
Replay<T> replay_clip(const ConvexPolyhedron<T>& R, const ConvexPolyhedron<T>& I, int ref_face, int inc,
                      double dn, const T& weld2, int unit) {
  constexpr bool fl = !number_traits<T>::is_exact;
  const double u = fl ? number_traits<T>::unit_roundoff : 0.0;
  const double g1 = gamma(1, u), g2 = gamma(2, u), g3 = gamma(3, u);
  Replay<T> out;
  const Vec3<T>& nr = R.plane(ref_face).normal;
  std::vector<ClipVertex<T>> poly, tmp;
  std::vector<double> ep, etmp;
  detail::incident_polygon(I, inc, ref_face, poly);
  ep.assign(poly.size(), 0.0);
  int h = R.face(ref_face).edge;
  for (int i = 0; i < R.face(ref_face).count && !poly.empty(); ++i, h = R.half_edge(h).next) {
    const ClipPlane<T> cp = detail::side_plane(R, h, nr);
    // the library's own step, and the replay of it with bounds
    clip_polygon(poly, cp, inc, tmp);
    etmp.clear();
    double dc = 0, cn = 0;
    V cd, vt;
    if constexpr (fl) {
      const Vec3<T> e(R.vertex(cp.head) - R.vertex(cp.tail));
      cd = vd(cp.normal);
      vt = vd(R.vertex(cp.tail));
      cn = nrm(cd);
      const double en = nrm(vd(e)), nn = nrm(vd(nr));
      dc = (g2 * nrm(bounds::abs_cross(vd(e), vd(nr))) + g1 * en * nn + (1 + g1) * en * dn) * kSlack;
      out.planes_n.push_back(cd / cn);
      out.planes_o.push_back(double(cp.offset) / cn);
    }
    const std::size_t n = poly.size();
    std::vector<T> hs(n);
    std::vector<double> eh(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      hs[k] = T(dot(cp.normal, poly[k].point) - cp.offset);
      if constexpr (fl) {
        const V p = vd(poly[k].point);
        eh[k] = (g3 * (bounds::abs_dot(cd, p) + bounds::abs_dot(cd, vt)) + g1 * std::abs(double(hs[k])) +
                 dc * nrm(p - vt) + (cn + dc) * ep[k]) *
                kSlack;
        out.rho = std::max(out.rho, eh[k] / std::max(cn - dc, 0.0));
      } else {
        if (hs[k] == T(0)) out.exact_zero = true;
      }
    }
    // Walk the library's output alongside the input (clip_polygon's loop):
    // copied vertices keep their bound, cut vertices get (M4).
    std::size_t w = 0;
    const T zero(0);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t k2 = (k + 1) % n;
      const bool cur_in = !(hs[k] > zero), nxt_in = !(hs[k2] > zero);
      auto cut_bound = [&]() {
        if constexpr (fl) {
          const double t = double(T(hs[k] / T(hs[k] - hs[k2])));
          const double Dabs = std::abs(double(T(hs[k] - hs[k2])));
          const double ea = eh[k], eb = eh[k2];
          const double den = Dabs * (1 - u) - ea - eb;
          const double dt = den > 0 ? g2 * std::abs(t) + (2 * ea + eb) / den : kInf;
          const double ba = nrm(vd(Vec3<T>(poly[k2].point - poly[k].point)));
          const double pa = ep[k], pb = ep[k2];
          const double e = ((1 - t) * pa + t * pb + dt * ((1 + g1) * ba + pa + pb) + g2 * t * (1 + g1) * ba +
                            g1 * nrm(vd(tmp[w].point))) *
                           kSlack;
          if (!std::isfinite(e)) out.infinite = true;
          return e;
        } else {
          return 0.0;
        }
      };
      if (cur_in) etmp.push_back(ep[k]), ++w;
      if (cur_in && !nxt_in && hs[k] < zero) {
        etmp.push_back(cut_bound());
        ++w;
      } else if (!cur_in && nxt_in && hs[k2] < zero) {
        etmp.push_back(cut_bound());
        ++w;
      }
    }
    if (w != tmp.size())
      throw std::logic_error("manifold replay: clip_polygon output size differs from the replay");
    if constexpr (fl) {
      // weld_polygon keeps the first vertex of each run of near-duplicates
      // (with its bound); replay it to know which bounds survive.
      std::vector<ClipVertex<T>> before = tmp;
      weld_polygon(tmp, weld2, unit);
      std::vector<double> ew;
      std::size_t j = 0;
      for (const auto& v : tmp) {
        while (j < before.size() && !(before[j].point == v.point)) ++j;
        if (j == before.size()) throw std::logic_error("manifold replay: weld output not found");
        ew.push_back(etmp[j]);
        ++j;
      }
      etmp = ew;
    } else {
      (void)weld2, (void)unit;  // exact: contact_manifold does not weld
    }
    poly.swap(tmp);
    ep.swap(etmp);
  }
  out.poly = std::move(poly);
  out.ep = std::move(ep);
  return out;
}

// ---------------------------------------------------------------------------
struct Recorder {
  CaseReport& rep;
  const CheckOptions& opt;
  int kept = 0;
  void aspect(const std::string& name, Classification k) { rep.details["manifold." + name].add(k); }
  void ratio(const std::string& name, double r) {
    if (!std::isfinite(r)) return;
    double& m = rep.maxima["manifold." + name];
    m = std::max(m, r);
  }
  void final(const std::string& cfg, Classification k, const std::function<std::string()>& detail) {
    rep.by_comparison["manifold"].add(k);
    rep.by_config["manifold/" + cfg].add(k);
    if (k == Classification::unexplained) {
      ++rep.unexplained_count;
      if (kept++ < opt.max_findings) rep.unexplained.push_back({"manifold", cfg, "gauss_map", detail()});
    }
  }
};

struct ExactSide {
  const ConvexPolyhedron<Q>& A;
  const ConvexPolyhedron<Q>& B;
  const SatResult<Q>& sat;
  ContactManifold<Q> all, red;  // reduce = false / true
  std::vector<double> nlenA, nlenB;
};

std::string ids_string(const auto& m) {
  std::string s;
  for (const auto& p : m.points) s += (s.empty() ? "" : ", ") + to_string(p.id);
  return "[" + s + "]";
}

template <class F>
struct FloatCheck {
  const ConvexPolyhedron<F>& A;
  const ConvexPolyhedron<F>& B;
  const ExactSide& E;
  const std::string cfg;
  Recorder& rec;
  double u = number_traits<F>::unit_roundoff;
  double g1 = gamma(1, u), g2 = gamma(2, u), g3 = gamma(3, u), g6 = gamma(6, u), g7 = gamma(7, u),
         g8 = gamma(8, u);
  std::ostringstream why;  // what differed, for a finding

  struct Kept {
    double ep, es, ex;  // position bound of the incident point, depth bound, position bound of `position`
  };

  FloatCheck(const ConvexPolyhedron<F>& a, const ConvexPolyhedron<F>& b, const ExactSide& e, std::string c,
             Recorder& r)
      : A(a), B(b), E(e), cfg(std::move(c)), rec(r) {}

  double delta_n(const ConvexPolyhedron<F>& p, const std::vector<double>& nlen, int f) const {
    const auto pts = p.plane_points(f);
    return bounds::delta_normal<F>(Vec3<F>(pts[1] - pts[0]), Vec3<F>(pts[2] - pts[0]),
                                   nlen[static_cast<std::size_t>(f)]);
  }

  // The SAT separation bound (error_bounds.hpp (3) / (4)), as check.cpp's
  // FloatSide::bound for the Gauss map.
  double sat_bound(const Feature& f) const {
    auto face = [&](const ConvexPolyhedron<F>& p, const std::vector<double>& nlen, int fi,
                    const ConvexPolyhedron<F>& q) {
      const double dnf = delta_n(p, nlen, fi);
      double m = 0;
      for (const auto& v : q.vertices())
        m = std::max(m, bounds::face_bound<F>(p.plane(fi).normal, p.plane_points(fi)[0], v, dnf));
      return m;
    };
    switch (f.type) {
      case FeatureType::FaceA:
        return face(A, E.nlenA, f.a, B);
      case FeatureType::FaceB:
        return face(B, E.nlenB, f.b, A);
      case FeatureType::EdgePair: {
        const Vec3<F> da = A.edge_direction(f.a), db = B.edge_direction(f.b);
        const Vec3<Q> ne = cross(E.A.edge_direction(f.a), E.B.edge_direction(f.b));
        const double dnf = bounds::delta_normal<F>(da, db, bounds::sqrt_lower(squared_norm(ne).get_d()));
        Vec3<F> n = cross(da, db);
        const F len = std::sqrt(squared_norm(n));
        n = Vec3<F>(n[0] / len, n[1] / len, n[2] / len);
        const Vec3<F> w(B.vertex(B.edge_tail(f.b)) - A.vertex(A.edge_tail(f.a)));
        return bounds::edge_bound<F>(n, w, dnf);
      }
      default:
        break;  // feature types without a bound here: no value is compared
    }
    return kInf;
  }

  Classification run(const SatResult<F>& r) {
    const ContactManifold<Q>& me = E.all;
    ManifoldOptions all_opt;
    all_opt.reduce = false;
    const ContactManifold<F> mf = contact_manifold(A, B, r, all_opt);
    const ContactManifold<F> mr = contact_manifold(A, B, r);
    // ---- empty / non-empty: the overlap verdicts differ at a boundary ----
    if (mf.empty() != me.empty()) {
      const double b = sat_bound(r.feature);
      why << "one manifold is empty: " << cfg << " " << mf.size() << " points, exact " << me.size()
          << " (exact separation " << num(to_double(E.sat.separation)) << ", bound " << num(b) << ")";
      Classification k = sign(E.sat.separation) == 0        ? Classification::exact_zero
                         : within(0.0, E.sat.separation, b) ? Classification::explained
                                                            : Classification::unexplained;
      rec.aspect("points", k);
      return k;
    }
    if (mf.empty()) {
      rec.aspect("points", Classification::agree);
      return Classification::agree;
    }
    if (mf.kind != me.kind) {
      why << "kind " << to_string(mf.kind) << " vs exact " << to_string(me.kind);
      rec.aspect("points", Classification::unexplained);
      return Classification::unexplained;
    }
    if (mf.kind == ContactKind::Edge) return edge(r, mf);
    if (mf.kind == ContactKind::Face) return face(mf, mr);
    return other_kind(mf);
  }

  // ---- a contact kind this comparison has no bounds for (e.g. a side
  // contact of coplanar polygons): ids and count only; a difference is
  // exact_zero when the exact SAT separation is exactly 0, else unexplained.
  Classification other_kind(const ContactManifold<F>& mf) {
    const auto& me = E.all;
    rec.rep.details["manifold.values_not_compared"].add(Classification::agree);
    bool same = mf.size() == me.size();
    for (int i = 0; same && i < mf.size(); ++i)
      same = mf.points[static_cast<std::size_t>(i)].id == me.points[static_cast<std::size_t>(i)].id;
    if (same) {
      rec.aspect("points", Classification::agree);
      return Classification::agree;
    }
    why << to_string(mf.kind) << " contact ids " << ids_string(mf) << " vs exact " << ids_string(me);
    const Classification k =
        sign(E.sat.separation) == 0 ? Classification::exact_zero : Classification::unexplained;
    rec.aspect("points", k);
    return k;
  }

  // ---- edge contact (M7) ----
  Classification edge(const SatResult<F>& r, const ContactManifold<F>& mf) {
    const auto& me = E.all;
    if (mf.size() != 1 || me.size() != 1 || !(mf.points[0].id == me.points[0].id)) {
      why << "edge contact ids " << ids_string(mf) << " vs exact " << ids_string(me);
      rec.aspect("points", Classification::unexplained);
      return Classification::unexplained;
    }
    rec.aspect("points", Classification::agree);
    const auto& c = mf.points[0];
    const auto& ce = me.points[0];
    // depth: the SAT separation
    const double bs = sat_bound(r.feature);
    const double sf = to_double(c.separation);
    Classification k = Classification::agree;
    const bool depth_ok = within(sf, ce.separation, bs);
    rec.aspect("depth", depth_ok ? Classification::agree : Classification::unexplained);
    if (!depth_ok) {
      why << "edge contact depth " << num(-sf) << " vs exact " << num(-to_double(ce.separation)) << " bound "
          << num(bs) << "; ";
      k = Classification::unexplained;
    }
    // position
    const int ea = r.feature.a, eb = r.feature.b;
    const Vec3<F> da = A.edge_direction(ea), db = B.edge_direction(eb);
    const Vec3<F> pa = A.vertex(A.edge_tail(ea)), pb = B.vertex(B.edge_tail(eb));
    const Vec3<F> rr(pa - pb);
    const double X = nrm(vd(da)), Y = nrm(vd(db)), Rn = nrm(vd(rr));
    const F a = dot(da, da), e = dot(db, db), b = dot(da, db), cc = dot(da, rr), f = dot(db, rr);
    const F den = a * e - b * b;
    const double dD = (g8 + 3 * g6 + 2 * g1) * X * X * Y * Y;
    const double N = double(F(b * f - cc * e));
    const double dN = 6 * g6 * X * Y * Y * Rn + g1 * std::abs(N);
    const double s_raw = double(den) > 0 ? double(F(N / double(den))) : 0.0;
    const double ds = std::abs(double(den)) > dD
                          ? (dN + std::abs(s_raw) * dD) / (std::abs(double(den)) - dD) + g1 * std::abs(s_raw)
                          : kInf;
    // the float s and t as the library computed them: from point_a/point_b
    // we only need magnitudes <= 1 (clamped), so use 1 as their bound
    const double smax = 1.0, tmax = 1.0;
    const double bs_ = std::abs(double(b)) * smax;
    const double dt =
        (g6 * X * Y * smax + X * Y * ds + g6 * Y * Rn + 2 * g1 * (bs_ + bs_ + std::abs(double(f)))) /
            (Y * Y * (1 - g6)) +
        (g6 + g1) * tmax;
    const double ds2 =
        (g6 * X * (Rn + Y) + g1 * (std::abs(double(b)) + std::abs(double(cc)))) / (X * X * (1 - g6)) +
        g1 * smax;
    const double Ds = ds + ds2 + (Y / X) * dt, Dt = dt;
    const double epa = (X * Ds + g1 * smax * X + g2 * (smax * X + nrm(vd(c.point_a)))) * kSlack;
    const double epb = (Y * Dt + g1 * tmax * Y + g2 * (tmax * Y + nrm(vd(c.point_b)))) * kSlack;
    const double ex = ((epa + epb) / 2 + g1 * nrm(vd(c.position))) * kSlack;
    const Q d2 = squared_norm(Vec3<Q>(vq(c.position) - ce.position));
    const bool pos_ok = !std::isfinite(ex) || d2 <= Q(ex) * Q(ex);
    rec.ratio("position", std::sqrt(d2.get_d()) / ex);
    rec.ratio("depth", std::abs(sf - to_double(ce.separation)) / bs);
    rec.aspect("position", pos_ok ? Classification::agree : Classification::unexplained);
    if (!pos_ok) {
      why << "edge contact position error " << num(std::sqrt(d2.get_d())) << " > bound " << num(ex);
      k = Classification::unexplained;
    }
    rec.aspect("reduction", Classification::agree);
    return k;
  }

  // ---- face contact (M1)-(M6), (M8) ----
  Classification face(const ContactManifold<F>& mf, const ContactManifold<F>& mr) {
    const auto& me = E.all;
    const bool ref_a = mf.reference_shape == 0;
    const ConvexPolyhedron<F>& R = ref_a ? A : B;
    const ConvexPolyhedron<F>& I = ref_a ? B : A;
    const ConvexPolyhedron<Q>& Re = ref_a ? E.A : E.B;
    const ConvexPolyhedron<Q>& Ie = ref_a ? E.B : E.A;
    const auto& nlenR = ref_a ? E.nlenA : E.nlenB;
    const auto& nlenI = ref_a ? E.nlenB : E.nlenA;
    const int rf = mf.reference_face;
    if (me.reference_shape != mf.reference_shape || me.reference_face != rf) {
      why << "reference face differs with the same SAT feature";
      rec.aspect("incident_face", Classification::unexplained);
      return Classification::unexplained;
    }
    const double dn = delta_n(R, nlenR, rf);
    // -- incident face --
    if (mf.incident_face != me.incident_face) {
      auto score_e = [&](int g) {
        const Vec3<Q>& N = Re.plane(rf).normal;
        const Vec3<Q>& M = Ie.plane(g).normal;
        return Separation<Q>{Q(-dot(N, M)), Q(squared_norm(N) * squared_norm(M))};
      };
      auto bound = [&](int g) {
        const V n = vd(R.plane(rf).normal), m = vd(I.plane(g).normal);
        return (g3 * bounds::abs_dot(n, m) + dn * nrm(m) + (1 + dn) * delta_n(I, nlenI, g)) * kSlack;
      };
      const int gf = mf.incident_face, ge = me.incident_face;
      const bool t = close(score_e(gf), score_e(ge), bound(gf) + bound(ge));
      why << "incident face " << gf << " vs exact " << ge << " (exact anti-parallelism "
          << num(to_double(score_e(gf))) << " vs " << num(to_double(score_e(ge))) << ", bounds "
          << num(bound(gf)) << " + " << num(bound(ge)) << ")";
      const Classification k = t ? Classification::tie : Classification::unexplained;
      rec.aspect("incident_face", k);
      return k;
    }
    rec.aspect("incident_face", Classification::agree);
    const int inc = mf.incident_face;
    // -- replay both clips --
    const double ext = std::min(A.extent(), B.extent());
    // (the library's weld: squared lengths in units of 2^unit, in range at every scale)
    const int unit = detail::manifold_scale_exponent(A, B);
    const F weld2 = detail::extent_tolerance(A, B, Tolerances<F>::kContactWeld, 2, unit);
    const double weld = std::ldexp(std::sqrt(double(weld2)), unit);  // (a length)
    const Replay<F> rpf = replay_clip(R, I, rf, inc, dn, weld2, unit);
    const Replay<Q> rpe = replay_clip(Re, Ie, rf, inc, 0.0, Q(0), 0);
    // A cut of a segment lying within its bound of a side plane has no finite
    // bound (M4): counted, so that vacuous comparisons are visible.
    if (rpf.infinite || !std::isfinite(rpf.rho))
      rec.rep.details["manifold.ill_conditioned"].add(Classification::agree);
    // -- the kept points with their bounds (M5), (M6) --
    const Vec3<F>& n = R.plane(rf).normal;
    const V nd = vd(n), p0 = vd(R.plane_points(rf)[0]);
    const double nn = nrm(nd);
    std::vector<Kept> kept;
    double es_max = 0, ep_max = 0;
    // (M5), (M6) for an incident point p with position bound ep; false when
    // p is above the reference plane (not kept, margin 0).
    auto bound_point = [&](const Vec3<F>& p, double ep, Kept& out) {
      const F s = F(dot(n, p) - R.plane(rf).offset);
      ep_max = std::max(ep_max, ep);
      const V pd = vd(p);
      const double es = (g3 * (bounds::abs_dot(nd, pd) + bounds::abs_dot(nd, p0)) + g1 * std::abs(double(s)) +
                         dn * nrm(pd - p0) + (nn + dn) * ep) *
                        kSlack;
      es_max = std::max(es_max, es);
      const V q = pd - nd * double(s);
      const double eq = ep + dn * std::abs(double(s)) + es + g1 * (nn * std::abs(double(s)) + nrm(q));
      const double ex = ((ep + eq) / 2 + g1 * nrm((pd + q) / 2)) * kSlack;
      out = {ep, es, ex};
      return !(s > F(0));
    };
    for (std::size_t i = 0; i < rpf.poly.size(); ++i) {
      Kept k{};
      if (bound_point(rpf.poly[i].point, rpf.ep[i], k)) kept.push_back(k);
    }
    // the replay must be the library's computation
    bool same_replay = static_cast<int>(kept.size()) == mf.size();
    if (mf.support_fallback) {
      // contact_manifold's safety net: no clipped point below the reference
      // face, the support vertex alone (an exact float vertex: ep = 0).
      Kept k{};
      const auto& c = mf.points[0];
      bound_point(ref_a ? c.point_b : c.point_a, 0.0, k);
      same_replay = kept.empty() && mf.size() == 1;
      kept.assign(1, k);
    } else {
      std::size_t j = 0;
      for (int i = 0; same_replay && i < mf.size(); ++i) {
        const auto& c = mf.points[static_cast<std::size_t>(i)];
        const Vec3<F>& inc_pt = ref_a ? c.point_b : c.point_a;
        while (j < rpf.poly.size() && !(rpf.poly[j].point == inc_pt)) ++j;
        same_replay = j < rpf.poly.size();
        ++j;
      }
    }
    if (!same_replay) {
      why << "internal: the clip replay does not reproduce contact_manifold (" << mf.size()
          << " points, replay " << kept.size() << ")";
      rec.aspect("points", Classification::unexplained);
      return Classification::unexplained;
    }
    // -- match by id --
    std::vector<int> match(static_cast<std::size_t>(mf.size()), -1);
    std::vector<bool> used(static_cast<std::size_t>(me.size()), false);
    for (int i = 0; i < mf.size(); ++i)
      for (int j = 0; j < me.size(); ++j)
        if (!used[static_cast<std::size_t>(j)] &&
            mf.points[static_cast<std::size_t>(i)].id == me.points[static_cast<std::size_t>(j)].id) {
          match[static_cast<std::size_t>(i)] = j;
          used[static_cast<std::size_t>(j)] = true;
          break;
        }
    // The safety net used on one side only: nothing matches (the points of
    // each side must be explained by the other's boundaries).
    const bool fallback_differs = mf.support_fallback != me.support_fallback;
    if (fallback_differs) {
      std::fill(match.begin(), match.end(), -1);
      std::fill(used.begin(), used.end(), false);
    }
    bool same_ids = mf.size() == me.size() && !fallback_differs;
    for (int i = 0; same_ids && i < mf.size(); ++i) same_ids = match[static_cast<std::size_t>(i)] == i;
    // -- matched points: depth and position within their bounds --
    Classification kvals = Classification::agree;
    for (int i = 0; i < mf.size(); ++i) {
      const int j = match[static_cast<std::size_t>(i)];
      if (j < 0) continue;
      const auto& c = mf.points[static_cast<std::size_t>(i)];
      const auto& ce = me.points[static_cast<std::size_t>(j)];
      const Kept& kb = kept[static_cast<std::size_t>(i)];
      const double sf = to_double(c.separation);
      if (std::isfinite(kb.es)) {
        rec.ratio("depth", std::abs(sf - to_double(ce.separation)) / kb.es);
        if (!within(sf, ce.separation, kb.es)) {
          why << "point " << to_string(c.id) << " depth " << num(-sf) << " vs exact "
              << num(-to_double(ce.separation)) << " beyond bound " << num(kb.es) << "; ";
          kvals = Classification::unexplained;
        }
      }
      if (std::isfinite(kb.ex)) {
        const Q d2 = squared_norm(Vec3<Q>(vq(c.position) - ce.position));
        rec.ratio("position", std::sqrt(d2.get_d()) / kb.ex);
        if (d2 > Q(kb.ex) * Q(kb.ex)) {
          why << "point " << to_string(c.id) << " position error " << num(std::sqrt(d2.get_d()))
              << " beyond bound " << num(kb.ex) << "; ";
          kvals = Classification::unexplained;
        }
      }
    }
    rec.aspect("depth_position", kvals);
    // -- unmatched points: at a boundary up to the bounds? --
    Classification kpts = Classification::agree;
    if (!same_ids) {
      std::vector<V> fpoly, epoly;
      for (const auto& v : rpf.poly) fpoly.push_back(vd(v.point));
      for (const auto& v : rpe.poly) epoly.push_back(vd(v.point));
      const double slack = 0x1p-40 * (ext + nrm(p0));
      auto near_boundary = [&](const V& x, double tau, const std::vector<V>& other) {
        const double rho = rpf.rho + es_max;
        if (poly_dist(x, other) <= tau + rho + weld + slack) return true;
        for (std::size_t s = 0; s < rpf.planes_n.size(); ++s)
          if (std::abs(rpf.planes_n[s].dot(x) - rpf.planes_o[s]) <= tau + rpf.rho + slack) return true;
        return std::abs(nd.dot(x - p0) / nn) <= tau + es_max + slack;
      };
      bool all_ok = true;
      std::string first_bad;
      for (int i = 0; i < mf.size(); ++i) {
        if (match[static_cast<std::size_t>(i)] >= 0) continue;
        const auto& c = mf.points[static_cast<std::size_t>(i)];
        const V x = vd(ref_a ? c.point_b : c.point_a);
        if (!near_boundary(x, kept[static_cast<std::size_t>(i)].ep, epoly)) {
          all_ok = false;
          if (first_bad.empty()) first_bad = cfg + " point " + to_string(c.id);
        }
      }
      for (int j = 0; j < me.size(); ++j) {
        if (used[static_cast<std::size_t>(j)]) continue;
        const auto& c = me.points[static_cast<std::size_t>(j)];
        const V x = vd(ref_a ? c.point_b : c.point_a);
        if (!near_boundary(x, ep_max, fpoly)) {
          all_ok = false;
          if (first_bad.empty()) first_bad = "exact point " + to_string(c.id);
        }
      }
      // exact_zero: the difference comes from a quantity that is exactly 0 in
      // exact arithmetic: an exact point without a partner lies exactly on the
      // reference plane or exactly on a side plane it was not made by; for a
      // float point without a partner, such an exact clipped vertex lies
      // within its tolerance.  Otherwise explained.
      struct SideQ {
        Vec3<Q> c;
        Q off;
        int edge, tail, head;
      };
      std::vector<SideQ> sides;
      {
        int he = Re.face(rf).edge;
        for (int i = 0; i < Re.face(rf).count; ++i, he = Re.half_edge(he).next) {
          const int t = Re.half_edge(he).origin, hd = Re.half_edge(Re.half_edge(he).next).origin;
          SideQ sq{cross(Vec3<Q>(Re.vertex(hd) - Re.vertex(t)), Re.plane(rf).normal), Q(0), he / 2, t, hd};
          sq.off = dot(sq.c, Re.vertex(t));
          sides.push_back(sq);
        }
      }
      // idr: the reference-side feature first (ClipVertex order)
      auto exact_zero_at = [&](const Vec3<Q>& x, const ContactFeatureId& idr) {
        if (sgn(Q(dot(Re.plane(rf).normal, x) - Re.plane(rf).offset)) == 0) return true;
        for (const auto& sq : sides) {
          const bool own =
              (idr.a.kind == ShapeFeatureKind::Edge && idr.a.index == sq.edge) ||
              (idr.a.kind == ShapeFeatureKind::Vertex && (idr.a.index == sq.tail || idr.a.index == sq.head));
          if (!own && sgn(Q(dot(sq.c, x) - sq.off)) == 0) return true;
        }
        return false;
      };
      bool ez = false;
      for (int j = 0; j < me.size() && !ez; ++j) {
        if (used[static_cast<std::size_t>(j)]) continue;
        const auto& c = me.points[static_cast<std::size_t>(j)];
        ez = exact_zero_at(ref_a ? c.point_b : c.point_a, ref_a ? c.id : c.id.swapped());
      }
      for (int i = 0; i < mf.size() && !ez; ++i) {
        if (match[static_cast<std::size_t>(i)] >= 0) continue;
        const auto& c = mf.points[static_cast<std::size_t>(i)];
        const V x = vd(ref_a ? c.point_b : c.point_a);
        const double tol = kept[static_cast<std::size_t>(i)].ep + rpf.rho + es_max + weld + slack;
        for (const auto& v : rpe.poly)
          if ((vd(v.point) - x).norm() <= tol && exact_zero_at(v.point, v.id)) ez = true;
      }
      kpts = !all_ok ? Classification::unexplained
             : ez    ? Classification::exact_zero
                     : Classification::explained;
      why << "clipped points differ: " << cfg << " " << ids_string(mf) << " vs exact " << ids_string(me);
      if (!all_ok) why << "; not near any boundary: " << first_bad;
      why << " (largest position bound " << num(ep_max) << ", height bound as distance " << num(rpf.rho)
          << ", depth bound " << num(es_max) << ", weld " << num(weld) << "); ";
    }
    rec.aspect("points", kpts);
    if (mf.support_fallback) rec.aspect("support_fallback", kpts);
    if (me.support_fallback) rec.aspect("support_fallback_exact", kpts);
    if (fallback_differs)
      why << "support-vertex safety net: " << cfg << " " << mf.support_fallback << ", exact "
          << me.support_fallback << "; ";
    // -- the reduction --
    Classification kred = Classification::agree;
    bool same_red = mr.size() == E.red.size();
    for (int i = 0; same_red && i < mr.size(); ++i)
      same_red = mr.points[static_cast<std::size_t>(i)].id == E.red.points[static_cast<std::size_t>(i)].id;
    if (!same_red) {
      if (!same_ids) {
        kred = kpts;  // different clipped points: the reduction follows
      } else {
        kred =
            reduction_tie(mf, mr, kept, dn, es_max, ext) ? Classification::tie : Classification::unexplained;
        why << "reduction " << ids_string(mr) << " vs exact " << ids_string(E.red) << "; ";
      }
    }
    rec.aspect("reduction", kred);
    return std::max({kvals, kpts, kred});
  }

  // (M8): is the float's reduction within the tolerance and bounds of the
  // exact optimum?  Same clipped points (ids in the same order) assumed.
  bool reduction_tie(const ContactManifold<F>& mf, const ContactManifold<F>& mr,
                     const std::vector<Kept>& kept, double dn, double es_max, double ext) {
    const auto& me = E.all;
    auto index_of = [&](const ContactFeatureId& id) {
      for (int i = 0; i < mf.size(); ++i)
        if (mf.points[static_cast<std::size_t>(i)].id == id) return i;
      return -1;
    };
    std::vector<int> xf, xe;
    for (const auto& p : mr.points) xf.push_back(index_of(p.id));
    for (const auto& p : E.red.points) xe.push_back(index_of(p.id));
    if (std::find(xf.begin(), xf.end(), -1) != xf.end() || std::find(xe.begin(), xe.end(), -1) != xe.end())
      return false;
    std::vector<Vec3<Q>> pe;
    for (const auto& p : me.points) pe.push_back(p.position);
    const double nlen = std::sqrt(squared_norm(me.normal).get_d());
    auto H = [&](const std::vector<int>& x) {
      return x.size() < 3 ? 0.0 : contact_hull_area2(pe, x, me.normal).get_d() / nlen;
    };
    const V nd = vd(mf.normal);
    auto dT = [&](int a, int b, int c) {
      const V pa = vd(mf.points[static_cast<std::size_t>(a)].position),
              pb = vd(mf.points[static_cast<std::size_t>(b)].position),
              pc = vd(mf.points[static_cast<std::size_t>(c)].position);
      const double ea = kept[static_cast<std::size_t>(a)].ex, eb = kept[static_cast<std::size_t>(b)].ex,
                   ec = kept[static_cast<std::size_t>(c)].ex;
      const V x = pb - pa, y = pc - pa;
      const double X = nrm(x), Y = nrm(y);
      return g7 * bounds::abs_dot(bounds::abs_cross(x, y), nd.cwiseAbs()) +
             nrm(nd) * ((ea + eb) * Y + (X + ea + eb) * (ea + ec)) + (X + ea + eb) * (Y + ea + ec) * dn;
    };
    auto dH = [&](const std::vector<int>& x) {
      double m = 0;
      for (std::size_t i = 0; i < x.size(); ++i)
        for (std::size_t j = i + 1; j < x.size(); ++j)
          for (std::size_t k = j + 1; k < x.size(); ++k) m = std::max(m, dT(x[i], x[j], x[k]));
      return 2 * m * kSlack;
    };
    const double area_tol = Tolerances<F>::kContactArea * ext * ext;
    // The reduction picks the deepest point first and then maximises the area
    // over the sets that contain it.  When the float's deepest point is
    // another one (a tie within key_tol: deep_ok below), its area is compared
    // with the exact optimum among the sets containing *that* point, which the
    // exact reduction gives when that point is made the unique deepest.
    std::vector<int> xo = xe;
    if (xf[0] != xe[0]) {
      std::vector<Q> keys(pe.size(), Q(1));
      keys[static_cast<std::size_t>(xf[0])] = Q(0);
      xo = reduce_contact_points<Q>(pe, keys, me.normal, Q(0), Q(0));
    }
    const double hf = H(xf), he = H(xo);
    const double slack = 0x1p-40 * (std::abs(he) + ext * ext);
    const bool area_ok = he - hf <= area_tol + dH(xf) + dH(xo) + slack;
    // the deepest point: the float's first point against the exact deepest
    const double key_tol = Tolerances<F>::kContactWeld * ext;
    const double sd = to_double(me.points[static_cast<std::size_t>(xf[0])].separation);
    const double se = to_double(me.points[static_cast<std::size_t>(xe[0])].separation);
    const bool deep_ok = sd - se <= key_tol + 2 * es_max + 0x1p-40 * ext;
    why << "exact area of the float's choice " << num(hf) << " vs the exact optimum "
        << (xf[0] != xe[0] ? "with its deepest point " : "") << num(he) << " (tolerance " << num(area_tol)
        << ", bounds " << num(dH(xf)) << " + " << num(dH(xo)) << "), deepest " << num(-sd) << " vs "
        << num(-se) << "; ";
    return area_ok && deep_ok;
  }
};

template <class F>
Classification check_with(const ConvexPolyhedron<F>& A, const ConvexPolyhedron<F>& B, const ExactSide& E,
                          const std::string& cfg, Recorder& rec, const SatResult<F>& r) {
  if (!(r.feature == E.sat.feature)) {
    rec.rep.details["manifold.skipped_feature_differs"].add(Classification::agree);
    return Classification::agree;
  }
  FloatCheck<F> fc{A, B, E, cfg, rec};
  Classification k;
  try {
    k = fc.run(r);
  } catch (const std::logic_error& e) {
    fc.why << "exception: " << e.what();
    k = Classification::unexplained;
  }
  rec.final(cfg, k, [&] { return fc.why.str(); });
  return k;
}

template <class F, class Policy>
void check_config(const ConvexPolyhedron<F>& A, const ConvexPolyhedron<F>& B, const ExactSide& E,
                  const std::string& cfg, Recorder& rec, const std::optional<SatResult<F>>& given) {
  check_with<F>(A, B, E, cfg, rec, given ? *given : run_sat<Policy>(Sat::gauss_map, A, B));
}

ExactSide make_exact(const ConvexPolyhedron<Q>& Aq, const ConvexPolyhedron<Q>& Bq,
                     const SatResult<Q>& exact_sat) {
  ExactSide E{Aq, Bq, exact_sat, {}, {}, {}, {}};
  ManifoldOptions all_opt;
  all_opt.reduce = false;
  E.all = contact_manifold(Aq, Bq, exact_sat, all_opt);
  E.red = contact_manifold(Aq, Bq, exact_sat);
  for (int f = 0; f < Aq.face_count(); ++f)
    E.nlenA.push_back(bounds::sqrt_lower(squared_norm(Aq.plane(f).normal).get_d()));
  for (int f = 0; f < Bq.face_count(); ++f)
    E.nlenB.push_back(bounds::sqrt_lower(squared_norm(Bq.plane(f).normal).get_d()));
  return E;
}

// Gmpq against mpq: identical ids and exactly equal values.
void check_gmpq(const ConvexPolyhedron<float>& Af, const ConvexPolyhedron<float>& Bf, const ExactSide& E,
                Recorder& rec, const CaseGaussMaps& maps) {
  using G = CGAL::Gmpq;
  std::optional<ConvexPolyhedron<G>> own_a, own_b;
  const ConvexPolyhedron<G>& A =
      maps.gmpq_a ? *maps.gmpq_a : own_a.emplace(ConvexPolyhedron<G>::convert_from(Af));
  const ConvexPolyhedron<G>& B =
      maps.gmpq_b ? *maps.gmpq_b : own_b.emplace(ConvexPolyhedron<G>::convert_from(Bf));
  const std::optional<SatResult<G>>& given = maps.gmpq;
  const SatResult<G> r = given ? *given : run_sat<policy::Plain>(Sat::gauss_map, A, B);
  ManifoldOptions all_opt;
  all_opt.reduce = false;
  std::ostringstream why;
  bool same = r.feature == E.sat.feature;
  for (int pass = 0; same && pass < 2; ++pass) {
    const ContactManifold<G> m = pass == 0 ? contact_manifold(A, B, r, all_opt) : contact_manifold(A, B, r);
    const ContactManifold<Q>& me = pass == 0 ? E.all : E.red;
    same = m.size() == me.size() && m.incident_face == me.incident_face;
    for (int i = 0; same && i < m.size(); ++i) {
      const auto& p = m.points[static_cast<std::size_t>(i)];
      const auto& q = me.points[static_cast<std::size_t>(i)];
      same = p.id == q.id && to_q(p.separation.num) == q.separation.num &&
             to_q(p.separation.norm2) == q.separation.norm2 && vq(p.position) == q.position;
    }
    if (!same)
      why << "gmpq manifold (" << (pass ? "reduced" : "all points") << ") " << ids_string(m)
          << " differs from mpq " << ids_string(me);
  }
  rec.final("gmpq", same ? Classification::agree : Classification::unexplained, [&] { return why.str(); });
}

void counts_line(std::ostream& out, const std::string& name, const Counts& c) {
  char line[200];
  std::snprintf(
      line, sizeof line, "  %-34s %10lld %10lld %10lld %8lld %11lld\n", name.c_str(),
      static_cast<long long>(c[Classification::agree]), static_cast<long long>(c[Classification::exact_zero]),
      static_cast<long long>(c[Classification::explained]), static_cast<long long>(c[Classification::tie]),
      static_cast<long long>(c[Classification::unexplained]));
  out << line;
}

}  // namespace

void check_manifolds(const ConvexPolyhedron<float>& Af, const ConvexPolyhedron<float>& Bf,
                     const ConvexPolyhedron<Q>& Aq, const ConvexPolyhedron<Q>& Bq,
                     const SatResult<Q>& exact_sat, const CaseGaussMaps& given, const CheckOptions& opt,
                     CaseReport& rep) {
  Recorder rec{rep, opt};
  const ExactSide E = make_exact(Aq, Bq, exact_sat);
  if (static_cast<std::int64_t>(Aq.edge_count()) * Bq.edge_count() <= opt.gmpq_pair_budget)
    check_gmpq(Af, Bf, E, rec, given);
  std::optional<ConvexPolyhedron<double>> own_a, own_b;
  const ConvexPolyhedron<double>& Ad =
      given.double_a ? *given.double_a : own_a.emplace(ConvexPolyhedron<double>::convert_from(Af));
  const ConvexPolyhedron<double>& Bd =
      given.double_b ? *given.double_b : own_b.emplace(ConvexPolyhedron<double>::convert_from(Bf));
  check_config<float, policy::Plain>(Af, Bf, E, "float_plain", rec, given.float_plain);
  check_config<double, policy::Plain>(Ad, Bd, E, "double_plain", rec, given.double_plain);
#if SEPAX_FUZZ_HAS_ROBUST
  check_config<float, policy::Robust>(Af, Bf, E, "float_robust", rec, given.float_robust);
  check_config<double, policy::Robust>(Ad, Bd, E, "double_robust", rec, given.double_robust);
#endif
}

Classification check_manifold_float(const ConvexPolyhedron<float>& Af, const ConvexPolyhedron<float>& Bf,
                                    const ConvexPolyhedron<Q>& Aq, const ConvexPolyhedron<Q>& Bq,
                                    const SatResult<Q>& exact_sat, const SatResult<float>& float_sat,
                                    const CheckOptions& opt, CaseReport& rep) {
  Recorder rec{rep, opt};
  const ExactSide E = make_exact(Aq, Bq, exact_sat);
  return check_with<float>(Af, Bf, E, "float_given", rec, float_sat);
}

void print_manifold_text(std::ostream& out, const std::map<std::string, Counts>& comparisons,
                         const std::map<std::string, Counts>& by_config,
                         const std::map<std::string, Counts>& details,
                         const std::map<std::string, double>& maxima) {
  const auto it = comparisons.find("manifold");
  if (it == comparisons.end()) return;
  char line[200];
  std::snprintf(line, sizeof line, "\n  %-34s %10s %10s %10s %8s %11s\n", "contact manifold (float vs exact)",
                "agree", "exact_zero", "explained", "tie", "unexplained");
  out << line;
  counts_line(out, "manifold", it->second);
  for (const auto& [k, c] : by_config)
    if (k.rfind("manifold/", 0) == 0) counts_line(out, "  " + k, c);
  for (const auto& [k, c] : details)
    if (k.rfind("manifold.", 0) == 0) counts_line(out, "  " + k, c);
  for (const auto& [k, v] : maxima)
    if (k.rfind("manifold.", 0) == 0) {
      std::snprintf(line, sizeof line, "  largest %s error / bound: %.3g\n", k.c_str() + 9, v);
      out << line;
    }
}

}  // namespace sepax::fuzz
