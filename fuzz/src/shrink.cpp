// The shrinker: see sepax/fuzz/shrink.hpp.
#include <sepax/fuzz/shrink.hpp>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

#include <Eigen/Geometry>
#include <sepax/fuzz/generators.hpp>

namespace sepax::fuzz {

FailureSignature signature_of(const CaseReport& r) {
  if (r.unexplained.empty()) return {};
  const Finding& f = r.unexplained.front();
  return {f.comparison, f.config, f.sat};
}

bool has_failure(const CaseReport& r, const FailureSignature& s) {
  if (!r.valid || s.comparison.empty()) return false;
  for (const auto& f : r.unexplained)
    if (f.comparison == s.comparison && f.config == s.config && f.sat == s.sat) return true;
  return false;
}

FailurePredicate same_failure(const FailureSignature& s, const CheckOptions& opt) {
  CheckOptions o = opt;
  // Findings are kept per comparison up to max_findings: keep them all, so a
  // finding of the signature is never hidden behind others of its comparison.
  o.max_findings = 1 << 20;
  return [s, o](const FuzzCase& c) { return has_failure(check_case_guarded(c, o), s); };
}

namespace {

using V = Vec3<double>;

V centroid(const ShapeSpec& s) {
  V c = V::Zero();
  for (const auto& v : s.vertices) c += v;
  return c / static_cast<double>(s.vertices.size());
}

double max_abs(const FuzzCase& c) {
  double m = 0;
  for (const auto* s : {&c.a, &c.b})
    for (const auto& v : s->vertices) m = std::max(m, v.cwiseAbs().maxCoeff());
  return m;
}

double extent(const ShapeSpec& s) {
  V lo = s.vertices.front(), hi = lo;
  for (const auto& v : s.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  return (hi - lo).norm();
}

// The smallest power of two >= x (x > 0).
double pow2_at_least(double x) {
  int e;
  const double m = std::frexp(x, &e);  // x = m 2^e, m in [0.5, 1)
  return m == 0.5 ? std::ldexp(1.0, e - 1) : std::ldexp(1.0, e);
}

// (+ 0.0 turns a rounded -0 into +0: "-0" in a reproducer only confuses.)
double round_to_grid(double x, double g) { return g * std::nearbyint(x / g) + 0.0; }

// Significant bits of x (0 for 0): 0.5 and 3 have 1 and 2, a random float 24.
int significant_bits(double x) {
  if (x == 0) return 0;
  int e;
  const double m = std::frexp(std::abs(x), &e);
  auto M = static_cast<std::uint64_t>(std::ldexp(m, 53));  // exact: x is a float (or a double)
  M >>= std::countr_zero(M);
  return static_cast<int>(std::bit_width(M));
}

// How complicated a case is: vertices first, then the significant bits of all
// coordinates.  Every kept step except the (at most two) rotations makes it
// strictly smaller, so the shrinker terminates even without a budget.
std::pair<std::size_t, long> complexity(const FuzzCase& c) {
  long bits = 0;
  for (const auto* s : {&c.a, &c.b})
    for (const auto& v : s->vertices)
      for (int k = 0; k < 3; ++k) bits += significant_bits(v[k]);
  return {c.a.vertices.size() + c.b.vertices.size(), bits};
}

std::optional<ShapeSpec> rehull(const std::vector<V>& pts) {
  if (pts.size() < 3) return std::nullopt;
  try {
    return hull_of(pts);
  } catch (...) {  // degenerate point set, or a hull builder failure: not a candidate
    return std::nullopt;
  }
}

// The shape's frame: z = unit normal of its largest face (Newell), x = its
// longest edge, orthogonalised.  Returns the rotation taking the frame to the
// identity (rows x, y, z).
Eigen::Matrix3d frame_inverse(const ShapeSpec& s) {
  double best_area = -1;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  for (const auto& f : s.faces) {
    V n = V::Zero();
    for (std::size_t i = 0; i < f.size(); ++i) {
      const V& p = s.vertices[static_cast<std::size_t>(f[i])];
      const V& q = s.vertices[static_cast<std::size_t>(f[(i + 1) % f.size()])];
      n += p.cross(q);
    }
    const double area = n.norm();
    if (!(area > best_area)) continue;
    V x = V::Zero();
    for (std::size_t i = 0; i < f.size(); ++i) {
      const V e = s.vertices[static_cast<std::size_t>(f[(i + 1) % f.size()])] -
                  s.vertices[static_cast<std::size_t>(f[i])];
      if (e.squaredNorm() > x.squaredNorm()) x = e;
    }
    const V z = n / area;
    x -= z * z.dot(x);
    if (!(x.norm() > 0) || !(area > 0)) continue;
    best_area = area;
    x.normalize();
    const V y = z.cross(x);
    R.row(0) = x.transpose();
    R.row(1) = y.transpose();
    R.row(2) = z.transpose();
  }
  return R;
}

class Shrinker {
 public:
  Shrinker(const FuzzCase& c, const FailurePredicate& fails, const ShrinkOptions& opt, ShrinkStats& st)
      : cur_(c), fails_(fails), opt_(opt), st_(st), t0_(std::chrono::steady_clock::now()) {}

  FuzzCase run() {
    ++st_.steps;
    if (!fails_(cur_)) return cur_;  // nothing to preserve
    for (;;) {
      const int before = st_.kept;
      remove_points();
      simplify_pose();
      round_coordinates();
      if (st_.out_of_budget || st_.kept == before) break;
    }
    return cur_;
  }

 private:
  FuzzCase cur_;
  const FailurePredicate& fails_;
  const ShrinkOptions& opt_;
  ShrinkStats& st_;
  std::chrono::steady_clock::time_point t0_;
  bool scene_rotated_ = false, b_rotated_ = false;  // each rotation is kept at most once

  bool budget_left() {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    st_.seconds = s;
    if (st_.steps >= opt_.max_steps || s >= opt_.max_seconds) st_.out_of_budget = true;
    return !st_.out_of_budget;
  }

  // The same point set (in any order): a rotation onto a symmetry of the
  // shape, or a re-hull that only renumbers, is not progress.
  static bool same(const ShapeSpec& x, const ShapeSpec& y) {
    if (x.vertices.size() != y.vertices.size()) return false;
    auto key = [](std::vector<V> v) {
      std::sort(v.begin(), v.end(), [](const V& p, const V& q) {
        return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3);
      });
      return v;
    };
    return key(x.vertices) == key(y.vertices);
  }

  // Evaluate a candidate; keep it when it still fails.  Unless `any` (the
  // rotations, kept at most once each), it must also be strictly simpler
  // (complexity): no cycles of steps that undo each other.
  bool attempt(const FuzzCase& cand, const std::string& what, bool any = false) {
    if (same(cand.a, cur_.a) && same(cand.b, cur_.b)) return false;
    if (!any && !(complexity(cand) < complexity(cur_))) return false;
    if (!budget_left()) return false;
    ++st_.steps;
    bool f = false;
    try {
      f = fails_(cand);
    } catch (...) {
      f = false;
    }
    if (!f) return false;
    cur_ = cand;
    ++st_.kept;
    st_.log.push_back(what);
    return true;
  }

  // The float polyhedron builds (a cheap check, not a predicate evaluation).
  static bool builds(const ShapeSpec& s) {
    try {
      std::vector<Vec3<float>> v;
      for (const auto& p : s.vertices)
        v.emplace_back(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
      (void)ConvexPolyhedron<float>::from_faces(std::move(v), s.faces);
      return true;
    } catch (...) {
      return false;
    }
  }

  // Move the vertices of one or both shapes by `map` (then round to float):
  // keep the face lists when the moved shapes are still valid, else re-hull.
  template <class Map>
  bool attempt_moved(bool move_a, bool move_b, const Map& map, const std::string& what, bool any = false) {
    FuzzCase c = cur_;
    for (auto [move, s] : {std::pair{move_a, &c.a}, std::pair{move_b, &c.b}}) {
      if (!move) continue;
      for (auto& v : s->vertices) v = map(v);
      round_to_float(*s);
    }
    if (builds(c.a) && builds(c.b)) return attempt(c, what, any);
    FuzzCase h = c;
    for (auto [move, s] : {std::pair{move_a, &h.a}, std::pair{move_b, &h.b}}) {
      if (!move) continue;
      auto r = rehull(s->vertices);
      if (!r) return false;
      *s = *r;
    }
    return attempt(h, what + ", re-hulled", any);
  }

  // ---- 1. remove points ----
  void remove_points() {
    for (const bool on_a : {true, false}) {
      const char* name = on_a ? "A" : "B";
      std::size_t chunk = std::max<std::size_t>(1, (on_a ? cur_.a : cur_.b).vertices.size() / 2);
      for (;;) {
        std::size_t i = 0;
        while (true) {
          const ShapeSpec& s = on_a ? cur_.a : cur_.b;
          const std::size_t n = s.vertices.size();
          if (i >= n || n <= 3 || !budget_left()) break;
          std::vector<V> rest;
          for (std::size_t k = 0; k < n; ++k)
            if (k < i || k >= i + chunk) rest.push_back(s.vertices[k]);
          auto h = rehull(rest);
          bool kept = false;
          if (h) {
            FuzzCase c = cur_;
            (on_a ? c.a : c.b) = *h;
            std::ostringstream w;
            w << "remove " << (n - rest.size()) << " vertices of " << name << " (" << n << " -> "
              << h->vertices.size() << ")";
            kept = attempt(c, w.str());
          }
          if (!kept) i += chunk;  // on success the next chunk has moved to i
        }
        if (chunk == 1 || st_.out_of_budget) break;
        chunk /= 2;
      }
    }
  }

  // ---- 2. pose ----
  void simplify_pose() {
    // Whole scene: A's centre to a coarse grid point near the origin.
    {
      const V ca = centroid(cur_.a);
      const double g = pow2_at_least(std::max(extent(cur_.a), 1e-30));
      const V t(round_to_grid(ca[0], g), round_to_grid(ca[1], g), round_to_grid(ca[2], g));
      if (!t.isZero()) {
        std::ostringstream w;
        w << "translate the scene by -(" << t.transpose() << ")";
        attempt_moved(
            true, true, [&](const V& v) { return V(v - t); }, w.str());
      }
    }
    // Whole scene: A's frame to the identity (about A's centre).
    if (!scene_rotated_) {
      const Eigen::Matrix3d R = frame_inverse(cur_.a);
      if (!R.isIdentity(0)) {
        const V ca = centroid(cur_.a);
        scene_rotated_ = attempt_moved(
            true, true, [&](const V& v) { return V(R * (v - ca) + ca); },
            "rotate the scene: A's frame to the identity", true);
      }
    }
    // B alone: its frame to the identity, or to A's frame (about B's centre).
    if (!b_rotated_) {
      const Eigen::Matrix3d RB = frame_inverse(cur_.b);
      const V cb = centroid(cur_.b);
      if (!RB.isIdentity(0))
        b_rotated_ = attempt_moved(
            false, true, [&](const V& v) { return V(RB * (v - cb) + cb); },
            "rotate B: its frame to the identity", true);
      if (!b_rotated_) {
        const Eigen::Matrix3d R = frame_inverse(cur_.a).transpose() * frame_inverse(cur_.b);
        if (!R.isIdentity(0))
          b_rotated_ = attempt_moved(
              false, true, [&](const V& v) { return V(R * (v - cb) + cb); },
              "rotate B: its frame to A's frame", true);
      }
    }
    // B alone: its offset from A rounded to k significant bits.
    {
      const V off = centroid(cur_.b) - centroid(cur_.a);
      const double m = off.cwiseAbs().maxCoeff();
      if (m > 0) {
        for (const int k : {0, 1, 2, 3, 4, 6, 8, 12, 16, 20}) {
          if (!budget_left()) break;
          const double g = std::ldexp(pow2_at_least(m), -k);
          const V r(round_to_grid(off[0], g), round_to_grid(off[1], g), round_to_grid(off[2], g));
          const V d = r - off;
          if (d.isZero()) break;
          std::ostringstream w;
          w << "round B's offset from A to the grid 2^" << std::ilogb(g);
          if (attempt_moved(
                  false, true, [&](const V& v) { return V(v + d); }, w.str()))
            break;
        }
      }
    }
  }

  // ---- 3. round coordinates ----
  void round_coordinates() {
    const double top = pow2_at_least(std::max(max_abs(cur_), 1e-30));
    for (const bool on_a : {true, false}) {
      for (const int k : {1, 2, 3, 4, 6, 8, 12, 16, 20, 24}) {
        if (!budget_left()) break;
        const double g = std::ldexp(top, -k);
        std::ostringstream w;
        w << "round " << (on_a ? "A" : "B") << "'s coordinates to the grid 2^" << std::ilogb(g);
        const auto map = [g](const V& v) {
          return V(round_to_grid(v[0], g), round_to_grid(v[1], g), round_to_grid(v[2], g));
        };
        // Skip grids that change nothing (the coordinates are already on them).
        const ShapeSpec& s = on_a ? cur_.a : cur_.b;
        bool changes = false;
        for (const auto& v : s.vertices) changes = changes || !(map(v) == v);
        if (!changes) break;
        if (attempt_moved(on_a, !on_a, map, w.str())) break;
      }
    }
  }
};

}  // namespace

FuzzCase shrink(const FuzzCase& c, const FailurePredicate& fails, const ShrinkOptions& opt,
                ShrinkStats* stats) {
  ShrinkStats local;
  ShrinkStats& st = stats ? *stats : local;
  st = ShrinkStats{};
  Shrinker s(c, fails, opt, st);
  return s.run();
}

std::string shrunk_path(const std::string& original_path, const std::string& out_dir) {
  const std::filesystem::path p(original_path);
  const std::filesystem::path dir = out_dir.empty() ? p.parent_path() : std::filesystem::path(out_dir);
  return (dir / (p.stem().string() + "-min.case")).string();
}

bool write_shrunk_reproducer(const std::string& path, const std::string& origin, const FuzzCase& c,
                             const CaseReport& r, const ShrinkOptions& opt, ShrinkStats* stats) {
  const FailureSignature sig = signature_of(r);
  if (sig.comparison.empty()) return false;
  ShrinkStats local;
  ShrinkStats& st = stats ? *stats : local;
  const FuzzCase m = shrink(c, same_failure(sig), opt, &st);
  CheckOptions all;
  all.max_findings = 1 << 20;
  const CaseReport mr = check_case_guarded(m, all);
  if (const auto dir = std::filesystem::path(path).parent_path(); !dir.empty())
    std::filesystem::create_directories(dir);
  std::ostringstream s;
  s << "sepax fuzz reproducer, shrunk: " << mr.unexplained_count << " unexplained disagreement(s)\n";
  s << "shrunk from " << origin << " preserving [" << sig.str() << "]: A " << c.a.vertices.size() << " -> "
    << m.a.vertices.size() << " vertices, B " << c.b.vertices.size() << " -> " << m.b.vertices.size()
    << " vertices; " << st.kept << " of " << st.steps << " steps kept in " << st.seconds << " s"
    << (st.out_of_budget ? " (budget spent: may shrink further)" : "") << "\n";
  for (const auto& l : st.log) s << "  step: " << l << "\n";
  int shown = 0;
  for (const auto& f : mr.unexplained)
    if (shown++ < 12) s << "[" << f.comparison << " " << f.config << " " << f.sat << "] " << f.detail << "\n";
  s << "replay: sepax fuzz --replay " << path << "\n";
  s << "audit:  sepax audit --case " << path;
  write_case_file(path, m, s.str());
  return true;
}

}  // namespace sepax::fuzz
