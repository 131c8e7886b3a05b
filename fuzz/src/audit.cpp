// `sepax audit`: everything the SAT decides for one pair, in float (or double)
// against exact arithmetic, with plain notes on what is degenerate.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <set>
#include <sstream>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <nlohmann/json.hpp>
#include <sepax/error.hpp>
#include <sepax/fuzz/campaign.hpp>
#include <sepax/fuzz/cli.hpp>
#include <sepax/fuzz/error_bounds.hpp>
#include <sepax/fuzz/generators.hpp>
#include <sepax/fuzz/sat_list.hpp>
#include <sepax/manifold_compare.hpp>
#include <sepax/robust/number_types.hpp>

namespace sepax::fuzz {

namespace {

using Q = mpq_class;
using Json = nlohmann::ordered_json;

Json feature_json(const Feature& f) { return Json{{"type", type_name(f.type)}, {"a", f.a}, {"b", f.b}}; }

std::string g(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.9g", x);
  return b;
}

double sep_d(const Separation<Q>& s) { return sepax::to_double(s); }

template <class F>
ConvexPolyhedron<F> build(const ShapeSpec& s) {
  std::vector<Vec3<F>> v;
  for (const auto& p : s.vertices) v.push_back(vec_from_double<F>(p));
  return ConvexPolyhedron<F>::from_faces(std::move(v), s.faces);
}

// The audit of c in F against exact mpq: the text report to `out`, and the
// same content as JSON in `j` (AuditOptions::json chooses which is printed).
template <class F>
void audit_as(const FuzzCase& c, std::ostream& out, Json& j) {
  const std::string fname(number_traits<F>::name);
  // Identical inputs: F polyhedra validated from the float coordinates, exact
  // images through the same plane triples.
  const auto Af0 = build<float>(c.a);
  const auto Bf0 = build<float>(c.b);
  const auto A = ConvexPolyhedron<F>::convert_from(Af0);
  const auto B = ConvexPolyhedron<F>::convert_from(Bf0);
  const auto Ae = ConvexPolyhedron<Q>::convert_from(Af0);
  const auto Be = ConvexPolyhedron<Q>::convert_from(Bf0);
  PlainKernel<F> k(A, B);
  PlainKernel<Q> ke(Ae, Be);
  std::vector<std::string> notes;

  j["number"] = fname;
  j["reference"] = "mpq";
  j["shapes"] = Json::object();
  auto describe = [&](const char* name, const ConvexPolyhedron<F>& p) {
    j["shapes"][name] = Json{{"vertices", p.vertex_count()},
                             {"edges", p.edge_count()},
                             {"faces", p.face_count()},
                             {"flat", p.is_flat()},
                             {"extent", double(p.extent())}};
    out << name << ": " << p.vertex_count() << " vertices, " << p.edge_count() << " edges, " << p.face_count()
        << " faces" << (p.is_flat() ? " (double-sided polygon: faces 0 and 1 are its two sides)" : "")
        << ", extent " << g(p.extent()) << "\n";
    if (p.is_flat())
      notes.push_back(std::string(name) +
                      " is a double-sided polygon: its two face normals are exactly opposite, "
                      "its edges' arcs are half great circles, and every edge of it has both faces");
  };
  out << "sepax audit (" << fname << " against exact mpq)\n";
  describe("A", A);
  describe("B", B);

  // ---- edge pairs ----
  std::vector<double> dA, dB;
  for (int f = 0; f < A.face_count(); ++f) {
    const auto p = A.plane_points(f);
    dA.push_back(bounds::delta_normal<F>(Vec3<F>(p[1] - p[0]), Vec3<F>(p[2] - p[0]),
                                         bounds::sqrt_lower(squared_norm(Ae.plane(f).normal).get_d())));
  }
  for (int f = 0; f < B.face_count(); ++f) {
    const auto p = B.plane_points(f);
    dB.push_back(bounds::delta_normal<F>(Vec3<F>(p[1] - p[0]), Vec3<F>(p[2] - p[0]),
                                         bounds::sqrt_lower(squared_norm(Be.plane(f).normal).get_d())));
  }
  out << "\nEdge pairs: the four triple products of the arc test in " << fname
      << " (value, then the exact sign in brackets; '!' marks a sign that differs,\n"
         "'0' an exact zero), the Minkowski-face verdict and the parallel flag in "
      << fname << "/exact ('!': they differ).\n";
  {
    char line[400];
    std::snprintf(line, sizeof line, "  %3s %3s |", "eA", "eB");
    out << line;
    for (const char* name : {"cba", "dba", "adc", "bdc"}) {
      std::snprintf(line, sizeof line, " %13s %4s %1s |", name, "sign", "");
      out << line;
    }
    std::snprintf(line, sizeof line, " %-9s %1s | %-9s\n", "mink", "", "parallel");
    out << line;
  }
  int exact_zeros = 0, sign_diffs = 0, parallel_exact = 0, parallel_tol = 0, verdict_diffs = 0;
  std::set<std::pair<int, int>> zero_pairs;
  j["edge_pairs"] = Json::array();
  for (int ea = 0; ea < A.edge_count(); ++ea) {
    for (int eb = 0; eb < B.edge_count(); ++eb) {
      const ArcSigns se = ke.arc_signs(ea, eb);
      const ArcSigns sf = k.arc_signs(ea, eb);
      const Vec3<F> da = A.edge_direction(ea), db = B.edge_direction(eb);
      const double v[4] = {double(dot(B.plane(B.edge_face(eb, 0)).normal, da)),
                           double(dot(B.plane(B.edge_face(eb, 1)).normal, da)),
                           -double(dot(A.plane(A.edge_face(ea, 0)).normal, db)),
                           -double(dot(A.plane(A.edge_face(ea, 1)).normal, db))};
      const int e4[4] = {se.cba, se.dba, se.adc, se.bdc};
      const int f4[4] = {sf.cba, sf.dba, sf.adc, sf.bdc};
      static constexpr const char* kNames[4] = {"cba", "dba", "adc", "bdc"};
      char line[400];
      std::snprintf(line, sizeof line, "  %3d %3d |", ea, eb);
      out << line;
      Json products = Json::array();
      for (int i = 0; i < 4; ++i) {
        const char* mark = f4[i] != e4[i] ? "!" : (e4[i] == 0 ? "0" : "");
        char bracket[8];
        std::snprintf(bracket, sizeof bracket, "[%+d]", e4[i]);
        std::snprintf(line, sizeof line, " %13.6g %4s %1s |", v[i], bracket, mark);
        out << line;
        products.push_back(Json{{"name", kNames[i]},
                                {"value", v[i]},
                                {"sign", f4[i]},
                                {"exact_sign", e4[i]},
                                {"differs", f4[i] != e4[i]}});
        if (e4[i] == 0) {
          ++exact_zeros;
          zero_pairs.insert({ea, eb});
        }
        if (f4[i] != e4[i]) ++sign_diffs;
      }
      const bool pe = ke.edges_parallel(ea, eb), pf = k.edges_parallel(ea, eb);
      parallel_exact += pe;
      parallel_tol += pf && !pe;
      verdict_diffs += sf.minkowski_face() != se.minkowski_face();
      const std::string mink =
          std::string(sf.minkowski_face() ? "yes" : "no") + "/" + (se.minkowski_face() ? "yes" : "no");
      const std::string par = std::string(pf ? "yes" : "no") + "/" + (pe ? "yes" : "no");
      std::snprintf(line, sizeof line, " %-9s %1s | %-9s%s\n", mink.c_str(),
                    sf.minkowski_face() != se.minkowski_face() ? "!" : "", par.c_str(), pf != pe ? " !" : "");
      out << line;
      j["edge_pairs"].push_back(
          Json{{"a", ea},
               {"b", eb},
               {"triple_products", std::move(products)},
               {"minkowski_face", Json{{"value", sf.minkowski_face()}, {"exact", se.minkowski_face()}}},
               {"parallel", Json{{"value", pf}, {"exact", pe}}}});
    }
  }

  // ---- candidate axes ----
  out << "\nCandidate axes: separation in " << fname << " against exact (positive: separated along it).\n";
  out << "  axis                     " << fname << " separation     exact separation        difference    "
      << fname << " error bound\n";
  struct Cand {
    Feature f;
    Separation<Q> se;
  };
  std::vector<Cand> cands;
  j["axes"] = Json::array();
  auto row = [&](const std::string& name, double vf, const Separation<Q>& se, double bnd) {
    char line[300];
    const double ed = sep_d(se);
    j["axes"].push_back(Json{{"axis", name},
                             {"separation", vf},
                             {"exact_separation", ed},
                             {"difference", vf - ed},
                             {"error_bound", bnd},
                             {"exact_zero", sign(se) == 0}});
    std::snprintf(line, sizeof line, "  %-22s %18.10g %20.12g %17.3g %16.3g%s\n", name.c_str(), vf, ed,
                  vf - ed, bnd, sign(se) == 0 ? "  exact zero" : "");
    out << line;
  };
  for (int f = 0; f < A.face_count(); ++f) {
    const auto q = k.face_query_a(f);
    const auto qe = ke.face_query_a(f);
    double bnd = 0;
    for (const auto& v : B.vertices())
      bnd = std::max(bnd, bounds::face_bound<F>(A.plane(f).normal, A.plane_points(f)[0], v,
                                                dA[static_cast<std::size_t>(f)]));
    row("faceA " + std::to_string(f) + " (vB " + std::to_string(qe.support_vertex) + ")",
        double(q.separation.num), qe.separation, bnd);
    cands.push_back({Feature::face_a(f, qe.support_vertex), qe.separation});
  }
  for (int f = 0; f < B.face_count(); ++f) {
    const auto q = k.face_query_b(f);
    const auto qe = ke.face_query_b(f);
    double bnd = 0;
    for (const auto& v : A.vertices())
      bnd = std::max(bnd, bounds::face_bound<F>(B.plane(f).normal, B.plane_points(f)[0], v,
                                                dB[static_cast<std::size_t>(f)]));
    row("faceB " + std::to_string(f) + " (vA " + std::to_string(qe.support_vertex) + ")",
        double(q.separation.num), qe.separation, bnd);
    cands.push_back({Feature::face_b(qe.support_vertex, f), qe.separation});
  }
  for (int ea = 0; ea < A.edge_count(); ++ea) {
    for (int eb = 0; eb < B.edge_count(); ++eb) {
      const bool me = ke.arc_signs(ea, eb).minkowski_face() && !ke.edges_parallel(ea, eb);
      const bool mf = k.arc_signs(ea, eb).minkowski_face() && !k.edges_parallel(ea, eb);
      if (!me && !mf) continue;
      const Separation<Q> se = ke.edge_separation(ea, eb);
      const Vec3<F> da = A.edge_direction(ea), db = B.edge_direction(eb);
      const Vec3<Q> ne = cross(Ae.edge_direction(ea), Be.edge_direction(eb));
      Vec3<F> n = cross(da, db);
      const F len = std::sqrt(squared_norm(n));
      n = Vec3<F>(n[0] / len, n[1] / len, n[2] / len);
      const double dn = bounds::delta_normal<F>(da, db, bounds::sqrt_lower(squared_norm(ne).get_d()));
      const double bnd =
          bounds::edge_bound<F>(n, Vec3<F>(B.vertex(B.edge_tail(eb)) - A.vertex(A.edge_tail(ea))), dn);
      std::string name = "edges " + std::to_string(ea) + " x " + std::to_string(eb);
      if (me != mf) name += me ? " (exact only)" : " (" + fname + " only)";
      row(name, double(k.edge_separation(ea, eb).num), se, bnd);
      if (me) cands.push_back({Feature::edges(ea, eb), se});
    }
  }

  // side axes: two flat shapes (best_axis.hpp)
  const bool flat_pair = A.is_flat() && B.is_flat();
  j["flat_pair"] = flat_pair;
  if (flat_pair) {
    out << "  (both shapes flat: the in-plane edge normals are candidates)\n";
    auto sides = [&](bool of_a) {
      const auto& p = of_a ? A : B;
      const auto& q = of_a ? B : A;
      const auto& dp = of_a ? dA : dB;
      for (int e = 0; e < p.edge_count(); ++e) {
        const auto qf = of_a ? k.side_query_a(e) : k.side_query_b(e);
        const auto qe = of_a ? ke.side_query_a(e) : ke.side_query_b(e);
        const double bnd =
            bounds::side_axis_bound<F>(p, e, q, dp[static_cast<std::size_t>(p.edge_face(e, 0))]);
        row(std::string(of_a ? "sideA " : "sideB ") + std::to_string(e) + (of_a ? " (vB " : " (vA ") +
                std::to_string(qe.support_vertex) + ")",
            double(qf.separation.num), qe.separation, bnd);
        {
          cands.push_back(
              {of_a ? Feature::side_a(e, qe.support_vertex) : Feature::side_b(qe.support_vertex, e),
               qe.separation});
        }
      }
    };
    sides(true);
    sides(false);
  }

  // ---- chosen features ----
  out << "\nChosen features (maximum separation; ties broken faceA < faceB < edges < sideA < sideB by "
         "index):\n";
  j["chosen"] = Json::array();
  auto show = [&](const std::string& cfg, const std::string& sat, bool overlap, const Feature& f, double s) {
    j["chosen"].push_back(Json{{"config", cfg},
                               {"sat", sat},
                               {"overlap", overlap},
                               {"feature", feature_json(f)},
                               {"feature_text", to_string(f)},
                               {"separation", s}});
    char line[300];
    std::snprintf(line, sizeof line, "  %-14s %-12s %-9s %-16s separation %.12g\n", cfg.c_str(), sat.c_str(),
                  overlap ? "overlap" : "separated", to_string(f).c_str(), s);
    out << line;
  };
  SatResult<Q> ref;
  for (Sat sat : all_sats()) {
    const auto r = run_sat<policy::Plain>(sat, Ae, Be);
    if (sat == Sat::gauss_map) ref = r;
    show("mpq", sat_name(sat), r.overlap, r.feature, r.separation_as_double());
  }
  {
    const auto Ep = ConvexPolyhedron<CGAL::Epeck::FT>::convert_from(Af0);
    const auto Eq = ConvexPolyhedron<CGAL::Epeck::FT>::convert_from(Bf0);
    for (Sat sat : all_sats()) {
      const auto r = run_sat<policy::Plain>(sat, Ep, Eq);
      show("epeck", sat_name(sat), r.overlap, r.feature, r.separation_as_double());
    }
  }
  for (Sat sat : all_sats()) {
    const auto r = run_sat<policy::Plain>(sat, A, B);
    show(fname + "_plain", sat_name(sat), r.overlap, r.feature, r.separation_as_double());
  }
#if SEPAX_FUZZ_HAS_ROBUST
  for (Sat sat : all_sats()) {
    const auto r = run_sat<policy::Robust>(sat, A, B);
    show(fname + "_robust", sat_name(sat), r.overlap, r.feature, r.separation_as_double());
  }
#endif

  // ---- contact manifold: how it was made, float against exact ----
  {
    ManifoldOptions mo;
    mo.record_steps = true;
    const auto rf = run_sat<policy::Plain>(Sat::gauss_map, A, B);
    const ContactManifold<F> mf = contact_manifold(A, B, rf, mo);
    const ContactManifold<Q> me = contact_manifold(Ae, Be, ref, mo);
    out << "\nContact manifold (from the Gauss-map result; clip the incident face by the side planes of the "
           "reference face, keep the points below it, reduce to at most 4):\n";
    Json jm = Json::object();
    auto show_manifold = [&](const std::string& cfg, const auto& m) {
      Json jx{{"config", cfg}, {"kind", to_string(m.kind)}, {"points", Json::array()}};
      if (m.kind == ContactKind::Face) {
        Json steps = Json::array();
        for (const auto& st : m.clip_steps)
          steps.push_back(Json{{"side_edge", st.side_edge},
                               {"vertices_in", st.vertices_in},
                               {"vertices_out", st.vertices_out}});
        jx["reference"] = m.reference_shape == 0 ? "A" : "B";
        jx["reference_face"] = m.reference_face;
        jx["incident_face"] = m.incident_face;
        jx["incident_faces_visited"] = m.incident_faces_visited;
        jx["clip_steps"] = std::move(steps);
        jx["candidate_points"] = m.candidate_points;
        jx["support_fallback"] = m.support_fallback;
      }
      for (const auto& pt : m.points) {
        const Vec3<double> p = vec_to_double(pt.position);
        jx["points"].push_back(Json{{"id", to_string(pt.id)},
                                    {"position", Json::array({p[0], p[1], p[2]})},
                                    {"separation", sepax::to_double(pt.separation)}});
      }
      jm[cfg == "mpq" ? "exact" : "value"] = std::move(jx);
      out << "  " << cfg << ": " << to_string(m.kind) << " contact, " << m.size() << " point(s)";
      if (m.kind == ContactKind::Face) {
        out << "; reference face " << m.reference_face << " of " << (m.reference_shape == 0 ? "A" : "B")
            << ", incident face " << m.incident_face << " of " << (m.reference_shape == 0 ? "B" : "A") << " ("
            << m.incident_faces_visited << " faces searched); clip steps:";
        for (const auto& st : m.clip_steps)
          out << " [side edge " << st.side_edge << ": " << st.vertices_in << " -> " << st.vertices_out << "]";
        out << "; " << m.candidate_points << " point(s) below the reference face before the reduction";
        if (m.support_fallback) out << "; support-vertex fallback";
      }
      out << "\n";
      for (const auto& pt : m.points) {
        const Vec3<double> x = vec_to_double(pt.position);
        char line[200];
        std::snprintf(line, sizeof line, "    %-24s at (%.9g, %.9g, %.9g)  separation %.12g\n",
                      to_string(pt.id).c_str(), x[0], x[1], x[2], sepax::to_double(pt.separation));
        out << line;
      }
    };
    show_manifold("mpq", me);
    show_manifold(fname + "_plain", mf);
    const ManifoldDifference d = compare_manifolds(mf, me);
    jm["comparison"] = Json{{"identical", d.identical()},
                            {"deepest_depth_error", d.deepest_depth_error},
                            {"max_depth_error", d.max_depth_error},
                            {"max_position_error", d.max_position_error}};
    j["manifold"] = std::move(jm);
    out << "  " << fname << " against exact: "
        << (d.identical() ? "same kind, faces, point count and ids" : "combinatorics differ")
        << "; deepest depth error " << g(d.deepest_depth_error) << ", max depth error "
        << g(d.max_depth_error) << ", max position error " << g(d.max_position_error) << "\n";
    if (!d.identical())
      notes.push_back("the " + fname + " contact manifold differs combinatorially from the exact one");
  }

  // ---- notes ----
  if (flat_pair) {
    bool coplanar = true;
    for (int v = 0; v < Be.vertex_count() && coplanar; ++v)
      coplanar =
          sign(Separation<Q>{Q(dot(Ae.plane(0).normal, Be.vertex(v)) - Ae.plane(0).offset), Q(1)}) == 0;
    if (coplanar)
      notes.push_back(
          "both shapes are flat and exactly in one plane: every face and edge-pair axis is the plane "
          "normal (separation 0); the in-plane edge normals (sideA/sideB) decide a gap");
  }
  if (parallel_exact)
    notes.push_back(std::to_string(parallel_exact) +
                    " edge pair(s) are exactly parallel (no edge axis; skipped by every SAT)");
  if (parallel_tol)
    notes.push_back(std::to_string(parallel_tol) + " edge pair(s) are not exactly parallel but within the " +
                    fname + " 'parallel' tolerance (" + g(Tolerances<F>::kParallel) + "): plain " + fname +
                    " skips them");
  if (exact_zeros) {
    std::string s = std::to_string(exact_zeros) +
                    " triple product(s) are exactly zero (an arc endpoint exactly on the other arc's plane: "
                    "a face normal exactly perpendicular to the other edge), in pairs";
    int shown = 0;
    for (const auto& [a, b] : zero_pairs) {
      if (shown++ == 12) {
        s += " ...";
        break;
      }
      s += " (" + std::to_string(a) + "," + std::to_string(b) + ")";
    }
    notes.push_back(s);
  }
  if (sign_diffs)
    notes.push_back(std::to_string(sign_diffs) + " triple-product sign(s) differ between " + fname +
                    " and exact (marked '!')");
  if (verdict_diffs)
    notes.push_back(std::to_string(verdict_diffs) + " Minkowski-face verdict(s) differ between " + fname +
                    " and exact");
  {
    int ties = 0;
    std::string s;
    for (const auto& cnd : cands) {
      if (cnd.f == ref.feature || sepax::compare(cnd.se, ref.separation) != 0) continue;
      if (ties++ < 8) s += " " + to_string(cnd.f);
    }
    if (ties)
      notes.push_back(std::to_string(ties) + " other candidate(s) tie exactly with the chosen " +
                      to_string(ref.feature) + ":" + s + (ties > 8 ? " ..." : "") +
                      " (the tie-break picks the first in feature order)");
  }
  if (sign(ref.separation) == 0)
    notes.push_back("the shapes touch exactly (maximum separation is exactly 0): reported as overlap");
  j["notes"] = notes;
  out << "\nNotes:\n";
  if (notes.empty()) out << "  nothing degenerate\n";
  for (const auto& n : notes) out << "  - " << n << "\n";
}

}  // namespace

int run_audit(const FuzzCase& c, const AuditOptions& opt, std::ostream& out) {
  std::ostringstream text;
  Json j;
  if (opt.use_double)
    audit_as<double>(c, text, j);
  else
    audit_as<float>(c, text, j);
  CheckOptions check;
  check.inject_fault = opt.inject_fault;
  const CaseReport r = check_case_guarded(c, check);
  Json findings = Json::array();
  for (const auto& f : r.unexplained)
    findings.push_back(
        Json{{"comparison", f.comparison}, {"config", f.config}, {"sat", f.sat}, {"detail", f.detail}});
  j["check"] =
      Json{{"valid", r.valid}, {"unexplained", r.unexplained_count}, {"findings", std::move(findings)}};
  if (opt.json) {
    out << j.dump() << "\n";
  } else {
    out << text.str() << "\nDifferential check of this case (all configurations): ";
    if (r.unexplained_count == 0) {
      out << "no unexplained disagreement\n";
    } else {
      out << r.unexplained_count << " UNEXPLAINED disagreement(s)\n";
      for (const auto& f : r.unexplained)
        out << "  [" << f.comparison << " " << f.config << " " << f.sat << "] " << f.detail << "\n";
    }
  }
  return r.unexplained_count == 0 ? 0 : 1;
}

}  // namespace sepax::fuzz
