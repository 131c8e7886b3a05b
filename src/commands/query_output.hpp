// src/commands/query_output.hpp
//
// How a query result is printed: as text, as the --json object, and as a
// batch output line.  Keys (JSON), in this order:
//   overlap     true when the shapes share a point (touching counts)
//   separation  signed distance along the reported axis (> 0 separated)
//   feature     {"type": "faceA"|"faceB"|"edges"|"sideA"|"sideB", "a": i, "b": j}:
//               faceA: a = face of A, b = support vertex of B;
//               faceB: a = support vertex of A, b = face of B;
//               edges: a = edge of A, b = edge of B;
//               sideA: a = edge of A, b = support vertex of B (two flat
//                      shapes in one plane: the edge's in-plane normal);
//               sideB: a = support vertex of A, b = edge of B
//   normal      [x, y, z] unit axis pointing from A towards B
//   number, algorithm, policy, stats      (query --json only)
//   manifold    {"kind": "none"|"face"|"edge"|"side", ["reference": "A"|"B",
//               "reference_face", "incident_face" (face contacts)],
//               "points": [{"position": [x,y,z], "separation": d, "id": "A:.../B:..."}]}
//               (query --json; batch lines unless --no-manifold)
#pragma once

#include <ostream>
#include <string>

#include "commands/sat_runner.hpp"
#include "json/json.hpp"

namespace sepax::cli {

json::Value feature_json(const Feature& f);
json::Value vector_json(const Vec3<double>& v);
json::Value manifold_json(const ManifoldOut& m);

/// The `query --json` object.
json::Value query_json(const RunOutcome& r, const RunConfig& cfg);

/// One batch output line's object, without the id (batch.hpp writes the id
/// first, as written in the input).
json::Value batch_result_json(const RunOutcome& r, bool with_manifold);

/// The human-readable report of `query`.
void print_query_text(std::ostream& out, const RunOutcome& r, const RunConfig& cfg, const std::string& name_a,
                      const std::string& name_b);

}  // namespace sepax::cli
