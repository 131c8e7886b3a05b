// Posed queries and warm sequences in the checking core: see
// sepax/fuzz/check_posed.hpp.
#include <sepax/fuzz/check_posed.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <gmpxx.h>

#include <sepax/fuzz/bitwise.hpp>
#include <sepax/fuzz/random.hpp>
#include <sepax/fuzz/recorder.hpp>
#include <sepax/fuzz/sat_list.hpp>
#include <sepax/prepared_shape.hpp>
#include <sepax/robust/number_types.hpp>

namespace sepax::fuzz {

namespace {

using Q = mpq_class;
using X = CGAL::Epeck::FT;

std::string num(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

// A pose as drawn (double): a rotation by a quaternion, then a translation.
// Each configuration rounds it to its own type through
// RigidTransform<F>::from_quaternion (normalised in double, then rounded).
struct PoseSpec {
  std::array<double, 4> q{1, 0, 0, 0};
  std::array<double, 3> t{0, 0, 0};
  template <class F>
  RigidTransform<F> get() const {
    return RigidTransform<F>::from_quaternion(q[0], q[1], q[2], q[3], Vec3<F>(F(t[0]), F(t[1]), F(t[2])));
  }
};

// The case's poses: pose_a random; the relative motion of B a rotation by a
// small angle about a random axis and a small translation; the warm sequence
// adds 1..8 further steps of a coherent motion.
struct Poses {
  PoseSpec a;
  std::array<double, 4> rel_q{1, 0, 0, 0};
  std::array<double, 3> rel_t{0, 0, 0};
  std::array<double, 3> step_axis{0, 0, 1};
  double step_angle = 0;
  std::array<double, 3> step_t{0, 0, 0};
  static constexpr int kWarmSteps = 8;

  // pose_b of step k (k = 0: the posed query's), as pose_a * delta_k with
  // delta_k = (rotation rel_q then k steps about step_axis, translation
  // rel_t + k step_t), composed in F.
  template <class F>
  RigidTransform<F> b(int k) const {
    const double h = 0.5 * step_angle * k, s = std::sin(h);
    const std::array<double, 4> sq{std::cos(h), s * step_axis[0], s * step_axis[1], s * step_axis[2]};
    // quaternion product sq * rel_q
    const auto& r = rel_q;
    const double w = sq[0] * r[0] - sq[1] * r[1] - sq[2] * r[2] - sq[3] * r[3];
    const double x = sq[0] * r[1] + sq[1] * r[0] + sq[2] * r[3] - sq[3] * r[2];
    const double y = sq[0] * r[2] - sq[1] * r[3] + sq[2] * r[0] + sq[3] * r[1];
    const double z = sq[0] * r[3] + sq[1] * r[2] - sq[2] * r[1] + sq[3] * r[0];
    const RigidTransform<F> delta = RigidTransform<F>::from_quaternion(
        w, x, y, z,
        Vec3<F>(F(rel_t[0] + k * step_t[0]), F(rel_t[1] + k * step_t[1]), F(rel_t[2] + k * step_t[2])));
    return a.get<F>() * delta;
  }
};

std::array<double, 3> unit3(Rng& r) {
  for (;;) {
    const double x = r.uniform(-1, 1), y = r.uniform(-1, 1), z = r.uniform(-1, 1);
    const double n = std::sqrt(x * x + y * y + z * z);
    if (n > 1e-3 && n <= 1) return {x / n, y / n, z / n};
  }
}

Poses draw_poses(std::uint64_t seed, double extent) {
  Rng r(case_seed(seed, name_hash("posed")));
  Poses p;
  for (;;) {
    const double w = r.uniform(-1, 1), x = r.uniform(-1, 1), y = r.uniform(-1, 1), z = r.uniform(-1, 1);
    const double n2 = w * w + x * x + y * y + z * z;
    if (n2 > 1e-6 && n2 <= 1) {
      p.a.q = {w, x, y, z};
      break;
    }
  }
  const auto ta = unit3(r);
  const double far = extent * std::exp(r.uniform(std::log(0.1), std::log(100.0)));
  for (int i = 0; i < 3; ++i) p.a.t[i] = ta[i] * far;
  const auto axis = unit3(r);
  const double angle = r.uniform(0, 0.05);
  p.rel_q = {std::cos(angle / 2), std::sin(angle / 2) * axis[0], std::sin(angle / 2) * axis[1],
             std::sin(angle / 2) * axis[2]};
  const auto dt = unit3(r);
  const double move = r.uniform(0, 0.05) * extent;
  for (int i = 0; i < 3; ++i) p.rel_t[i] = dt[i] * move;
  p.step_axis = unit3(r);
  p.step_angle = r.uniform(1e-4, 2e-2);
  const auto st = unit3(r);
  const double step = r.uniform(0, 0.01) * extent;
  for (int i = 0; i < 3; ++i) p.step_t[i] = st[i] * step;
  return p;
}

template <class T>
std::string describe(const char* what, const std::string& cfg, Sat sat, const SatResult<T>& x,
                     const SatResult<T>& y) {
  std::ostringstream s;
  s << what << ": " << cfg << " " << sat_name(sat) << ": overlap=" << x.overlap
    << " early_out=" << x.early_out << " feature " << to_string(x.feature) << " separation "
    << num(sepax::to_double(x.separation)) << "; against overlap=" << y.overlap
    << " early_out=" << y.early_out << " feature " << to_string(y.feature) << " separation "
    << num(sepax::to_double(y.separation));
  return s.str();
}

template <class F, class Policy>
void posed_config(const ConvexPolyhedron<F>& A, const ConvexPolyhedron<F>& B, const Poses& P,
                  const std::string& cfg, bool robust, Recorder& rec) {
  const CheckOptions& opt = rec.opt;
  const PreparedShape<F> pa(A), pb(B);
  const RigidTransform<F> xa = P.a.get<F>(), xb = P.b<F>(0);
  const ConvexPolyhedron<F> Bp = posed(B, relative_pose(xa, xb));
  const bool exact_ref =
      static_cast<std::int64_t>(A.edge_count()) * B.edge_count() <= opt.posed_exact_pair_budget;
  // The exact reference of the robust decisions: Epeck::FT (exact; its
  // interval filter decides most signs without rational arithmetic, in about
  // a quarter of mpq's time on these runs).  Overlap, feature and separation
  // sign are those of any exact type.
  std::optional<ConvexPolyhedron<X>> Aq, Bq;
  if (robust && exact_ref) {
    Aq = ConvexPolyhedron<X>::convert_from(A);
    Bq = ConvexPolyhedron<X>::convert_from(Bp);
  }
  const double brute_cost =
      static_cast<double>(A.edge_count()) * B.edge_count() * (A.vertex_count() + B.vertex_count());
  for (Sat sat : all_sats()) {
    const char* sn = sat_name(sat);
    if (sat == Sat::brute_force && brute_cost > static_cast<double>(opt.float_brute_budget)) {
      for (const char* cmp : {"posed", "warm"}) rec.skip(cmp, cfg, sn);
      if (robust) rec.skip("posed_exact", cfg, sn);
      continue;
    }
    // posed against pre-posed, bit for bit
    const SatResult<F> r = sat::run<Policy>(sat, pa, xa, pb, xb);
    SatResult<F> local = run_sat<Policy>(sat, A, Bp);
    const Vec3<F> local_axis = local.axis;
    local.axis = xa.rotate(local_axis);
    rec.add("posed", cfg, sn, same_bits(r, local) ? Classification::agree : Classification::unexplained, [&] {
      return describe("posed query differs from the query on (A, posed(B, X))", cfg, sat, r, local);
    });
    if (sat == Sat::gauss_map) {
      SatResult<F> rl = local;
      rl.axis = local_axis;
      ContactManifold<F> ml = contact_manifold(A, Bp, rl, ManifoldOptions{});
      for (auto& p : ml.points) {
        p.position = xa.apply(p.position);
        p.point_a = xa.apply(p.point_a);
        p.point_b = xa.apply(p.point_b);
      }
      ml.normal = r.axis;
      const ContactManifold<F> m = contact_manifold(pa, xa, pb, xb, r);
      rec.add("posed", cfg, "manifold",
              same_bits(m, ml) ? Classification::agree : Classification::unexplained, [&] {
                return cfg +
                       ": the posed contact manifold differs from the manifold of (A, posed(B, X)) mapped to "
                       "world "
                       "(" +
                       std::to_string(m.size()) + " against " + std::to_string(ml.size()) + " points)";
              });
    }
    // robust: exact decisions on the posed input
    if (robust) {
      if (!exact_ref ||
          (sat == Sat::brute_force && brute_cost > static_cast<double>(opt.exact_brute_budget))) {
        rec.skip("posed_exact", cfg, sn);
      } else {
        const SatResult<X> e = run_sat<policy::Plain>(sat, *Aq, *Bq);
        const bool ok =
            r.overlap == e.overlap && r.feature == e.feature && sign(r.separation) == sign(e.separation);
        rec.add("posed_exact", cfg, sn, ok ? Classification::agree : Classification::unexplained, [&] {
          std::ostringstream s;
          s << cfg << " " << sn << " posed: overlap=" << r.overlap << " feature " << to_string(r.feature)
            << "; epeck on the exact posed input: overlap=" << e.overlap << " feature "
            << to_string(e.feature) << " separation " << num(sepax::to_double(e.separation));
          return s.str();
        });
      }
    }
    // warm sequences: without early exit, and with an early exit at 2 % of
    // the shapes' extent
    double extent = 0;
    for (const auto* p : {&A, &B})
      for (const auto& v : p->vertices())
        for (int c = 0; c < 3; ++c) extent = std::max(extent, std::abs(double(v[c])));
    for (const bool early : {false, true}) {
      SatOptions o;
      o.early_out = early;
      o.margin = early ? 0.02 * extent : 0.0;
      SatCache<F> cache;
      Classification worst = Classification::agree;
      std::string why;
      for (int k = 0; k <= Poses::kWarmSteps; ++k) {
        const RigidTransform<F> xk = P.b<F>(k);
        // step 0 without an early exit is the posed query r itself (the same
        // call: default options, xk == xb): run once
        const SatResult<F> fresh = (!early && k == 0) ? r : sat::run<Policy>(sat, pa, xa, pb, xk, o);
        const SatResult<F> warm = sat::run<Policy>(sat, pa, xa, pb, xk, o, &cache);
        const bool ok = !early ? same_bits(warm, fresh)
                               : warm.overlap == fresh.overlap && warm.early_out == fresh.early_out &&
                                     (fresh.early_out || same_bits(warm, fresh));
        if (!ok && worst == Classification::agree) {
          worst = Classification::unexplained;
          why = describe(early ? "warm query with an early exit differs from the fresh one"
                               : "warm query differs from the fresh one",
                         cfg, sat, warm, fresh) +
                " at step " + std::to_string(k);
        }
      }
      rec.add("warm", cfg, sn, worst, [&] { return why; });
    }
  }
}

// Exact rational poses stay exact: mpq shapes at integer-quaternion poses
// against the mpq SAT on the shapes moved exactly.
void posed_rational(const ConvexPolyhedron<Q>& Aq, const ConvexPolyhedron<Q>& Bq, std::uint64_t seed,
                    Recorder& rec) {
  Rng r(case_seed(seed, name_hash("posed_rational")));
  auto pose = [&] {
    long q[4];
    do {
      for (long& c : q) c = r.uniform_int(-6, 6);
    } while (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0);
    const Vec3<Q> t(Q(r.uniform_int(-64, 64), 8), Q(r.uniform_int(-64, 64), 8), Q(r.uniform_int(-64, 64), 8));
    return from_integer_quaternion<Q>(q[0], q[1], q[2], q[3], t);
  };
  const RigidTransform<Q> xa = pose(), xb = pose();
  const PreparedShape<Q> pa(Aq), pb(Bq);
  const ConvexPolyhedron<Q> Aw = transformed(Aq, xa), Bw = transformed(Bq, xb);
  for (Sat sat : {Sat::gauss_map, Sat::traversal}) {
    const SatResult<Q> p = sat::run<policy::Plain>(sat, pa, xa, pb, xb);
    const SatResult<Q> w = run_sat<policy::Plain>(sat, Aw, Bw);
    const bool ok = p.overlap == w.overlap && p.feature == w.feature &&
                    sepax::compare(p.separation, w.separation) == 0 && p.axis == w.axis;
    rec.add("posed_rational", "mpq", sat_name(sat), ok ? Classification::agree : Classification::unexplained,
            [&] {
              return describe("posed query at exact rational poses differs from the exactly moved shapes",
                              "mpq", sat, p, w);
            });
  }
}

}  // namespace

void check_posed(const ConvexPolyhedron<float>& Af, const ConvexPolyhedron<float>& Bf,
                 const ConvexPolyhedron<double>& Ad, const ConvexPolyhedron<double>& Bd,
                 const ConvexPolyhedron<Q>& Aq, const ConvexPolyhedron<Q>& Bq, std::uint64_t seed,
                 const CheckOptions& opt, CaseReport& rep) {
  Recorder rec{rep, opt, {}};
  double extent = 0;
  for (const auto* p : {&Af, &Bf})
    for (const auto& v : p->vertices())
      for (int c = 0; c < 3; ++c) extent = std::max(extent, std::abs(double(v[c])));
  const Poses P = draw_poses(seed, extent > 0 ? extent : 1.0);
  posed_config<float, policy::Plain>(Af, Bf, P, "float_plain", false, rec);
  posed_config<double, policy::Plain>(Ad, Bd, P, "double_plain", false, rec);
#if SEPAX_FUZZ_HAS_ROBUST
  posed_config<float, policy::Robust>(Af, Bf, P, "float_robust", true, rec);
  posed_config<double, policy::Robust>(Ad, Bd, P, "double_robust", true, rec);
#endif
  if (static_cast<std::int64_t>(Af.edge_count()) * Bf.edge_count() <= opt.posed_exact_pair_budget)
    posed_rational(Aq, Bq, seed, rec);
  else
    for (Sat sat : {Sat::gauss_map, Sat::traversal}) rec.skip("posed_rational", "mpq", sat_name(sat));
}

}  // namespace sepax::fuzz
