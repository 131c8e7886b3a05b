// src/commands/query_output.cpp -- see query_output.hpp.
#include "commands/query_output.hpp"

#include <string>

namespace sepax::cli {

json::Value feature_json(const Feature& f) {
  return json::Value{{"type", type_name(f.type)}, {"a", f.a}, {"b", f.b}};
}

json::Value vector_json(const Vec3<double>& v) {
  return json::Value::array({json::number(v[0]), json::number(v[1]), json::number(v[2])});
}

namespace {

json::Value stats_json(const SatStats& s) {
  return json::Value{{"face_axes", static_cast<long long>(s.face_axes)},
                     {"edge_pairs", static_cast<long long>(s.edge_pairs)},
                     {"minkowski_faces", static_cast<long long>(s.minkowski_faces)},
                     {"side_axes", static_cast<long long>(s.side_axes)},
                     {"exact_fallbacks", static_cast<long long>(s.exact_fallbacks)}};
}

std::string counts_text(const ShapeCounts& c) {
  return std::to_string(c.vertices) + " vertices, " + std::to_string(c.edges) + " edges, " +
         std::to_string(c.faces) + " faces" + (c.flat ? " (flat)" : "");
}

std::string feature_text(const Feature& f) {
  const std::string a = std::to_string(f.a), b = std::to_string(f.b);
  switch (f.type) {
    case FeatureType::FaceA:
      return "faceA: face " + a + " of A, support vertex " + b + " of B";
    case FeatureType::FaceB:
      return "faceB: face " + b + " of B, support vertex " + a + " of A";
    case FeatureType::EdgePair:
      return "edges: edge " + a + " of A, edge " + b + " of B";
    case FeatureType::SideA:
      return "sideA: in-plane normal of edge " + a + " of A (coplanar polygons), support vertex " + b +
             " of B";
    case FeatureType::SideB:
      return "sideB: in-plane normal of edge " + b + " of B (coplanar polygons), support vertex " + a +
             " of A";
  }
  return "?";
}

}  // namespace

json::Value manifold_json(const ManifoldOut& m) {
  json::Value points = json::Value::array();
  for (const auto& p : m.points) {
    points.push_back(json::Value{
        {"position", vector_json(p.position)}, {"separation", json::number(p.separation)}, {"id", p.id}});
  }
  json::Value o{{"kind", m.kind}};
  if (m.kind == "face") {
    o["reference"] = m.reference_shape == 0 ? "A" : "B";
    o["reference_face"] = m.reference_face;
    o["incident_face"] = m.incident_face;
  } else if (m.kind == "side") {
    o["reference"] = m.reference_shape == 0 ? "A" : "B";
  }
  o["points"] = std::move(points);
  return o;
}

json::Value query_json(const RunOutcome& r, const RunConfig& cfg) {
  return json::Value{{"overlap", r.overlap},
                     {"separation", json::number(r.separation)},
                     {"feature", feature_json(r.feature)},
                     {"normal", vector_json(r.normal)},
                     {"number", name(cfg.number)},
                     {"algorithm", name(cfg.algorithm)},
                     {"policy", cfg.robust ? "robust" : "plain"},
                     {"stats", stats_json(r.stats)},
                     {"manifold", manifold_json(r.manifold)}};
}

json::Value batch_result_json(const RunOutcome& r, bool with_manifold) {
  json::Value o{{"overlap", r.overlap},
                {"separation", json::number(r.separation)},
                {"feature", feature_json(r.feature)},
                {"normal", vector_json(r.normal)}};
  if (with_manifold) o["manifold"] = manifold_json(r.manifold);
  return o;
}

void print_query_text(std::ostream& out, const RunOutcome& r, const RunConfig& cfg, const std::string& name_a,
                      const std::string& name_b) {
  out << "A:          " << name_a << " (" << counts_text(r.a) << ")\n"
      << "B:          " << name_b << " (" << counts_text(r.b) << ")\n"
      << "overlap:    " << (r.overlap ? "yes" : "no") << "\n"
      << "separation: " << json::number_text(r.separation) << "\n"
      << "feature:    " << feature_text(r.feature) << "\n"
      << "normal:     " << json::number_text(r.normal[0]) << " " << json::number_text(r.normal[1]) << " "
      << json::number_text(r.normal[2]) << "  (unit axis from A towards B)\n"
      << "arithmetic: " << name(cfg.number) << ", algorithm " << name(cfg.algorithm) << ", "
      << (cfg.robust ? "robust" : "plain") << " policy\n"
      << "stats:      " << r.stats.face_axes << " face axes, " << r.stats.edge_pairs << " edge pairs, "
      << r.stats.minkowski_faces << " Minkowski faces, "
      << (r.stats.side_axes > 0 ? std::to_string(r.stats.side_axes) + " side axes, " : std::string())
      << r.stats.exact_fallbacks << " exact fallbacks\n";
  const ManifoldOut& m = r.manifold;
  if (m.kind == "none") {
    out << "manifold:   none (no contact points)\n";
    return;
  }
  out << "manifold:   " << m.kind << " contact, " << m.points.size() << " point"
      << (m.points.size() == 1 ? "" : "s");
  if (m.kind == "face") {
    out << " (reference face " << m.reference_face << " of " << (m.reference_shape == 0 ? "A" : "B")
        << ", incident face " << m.incident_face << " of " << (m.reference_shape == 0 ? "B" : "A") << ", "
        << m.candidate_points << " clipped points before reduction)";
  } else if (m.kind == "side") {
    out << " (reference edge on " << (m.reference_shape == 0 ? "A" : "B") << ", coplanar polygons)";
  }
  out << "\n";
  for (const auto& p : m.points) {
    out << "  point " << json::number_text(p.position[0]) << " " << json::number_text(p.position[1]) << " "
        << json::number_text(p.position[2]) << "  separation " << json::number_text(p.separation) << "  "
        << p.id << "\n";
  }
}

}  // namespace sepax::cli
