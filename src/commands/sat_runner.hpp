// src/commands/sat_runner.hpp
//
// Runs one SAT query chosen at run time -- number type, algorithm, policy --
// on two shapes given as ShapeData, and reports the result in doubles.  This
// is the only translation unit of the command-line program that instantiates
// sepax's templates with exact types (and so includes CGAL and GMP).
//
//   number     float | double | exact (mpq_class: GMP rationals)
//   algorithm  brute (sat::brute_force) | gauss (sat::gauss_map) |
//              traversal (sat::traversal, when sepax/sat_traversal.hpp exists)
//   robust     policy::Robust (float/double only, when
//              sepax/robust/robust_kernel.hpp exists); otherwise policy::Plain
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <sepax/feature.hpp>
#include <sepax/sat.hpp>
#include <sepax/sat_result.hpp>
#include <sepax/vec3.hpp>

#include "commands/pose.hpp"
#include "io/shape_data.hpp"

namespace sepax::cli {

enum class NumberKind { Float, Double, Exact };
enum class AlgorithmKind { Brute, Gauss, Traversal };

struct RunConfig {
  NumberKind number = NumberKind::Double;
  AlgorithmKind algorithm = AlgorithmKind::Gauss;
  bool robust = false;
};

struct ShapeCounts {
  int vertices = 0, edges = 0, faces = 0;
  bool flat = false;
};

/// One contact point of the manifold, in doubles (reporting).
struct ContactOut {
  Vec3<double> position = Vec3<double>(0, 0, 0);  // midway between the points on A and B
  double separation = 0;                          // < 0 penetrating
  std::string id;                                 // "A:<feature>/B:<feature>" (contact_feature.hpp)
};

/// The contact manifold built from the SAT result (sepax/contact_manifold.hpp).
struct ManifoldOut {
  std::string kind = "none";  // none | face | edge
  int reference_shape = -1;   // face contacts: 0 = A, 1 = B
  int reference_face = -1;
  int incident_face = -1;
  int candidate_points = 0;  // points below the reference face before the reduction
  std::vector<ContactOut> points;
};

struct RunOutcome {
  bool overlap = false;
  double separation = 0;                        // signed, along the unit axis
  Feature feature;                              // see sepax/feature.hpp
  Vec3<double> normal = Vec3<double>(0, 0, 0);  // unit axis from A towards B
  SatStats stats;
  bool early_out = false;
  ShapeCounts a, b;
  ManifoldOut manifold;
};

/// The library's name for an algorithm (sepax/sat.hpp).
SatAlgorithm sat_algorithm(AlgorithmKind k);

const char* name(NumberKind k);
const char* name(AlgorithmKind k);
std::optional<NumberKind> parse_number_kind(std::string_view s);
std::optional<AlgorithmKind> parse_algorithm_kind(std::string_view s);

bool traversal_available();
bool robust_available();
bool hull_builder_available();

/// Empty when cfg can run in this build, else why not ("--robust needs ...").
std::string unsupported_reason(const RunConfig& cfg);

/// Build A and B (B posed when pose_b is given) in cfg.number and run the SAT.
/// Throws InvalidInput for bad shapes, std::invalid_argument for a config
/// that this build cannot run.
RunOutcome run_sat(const io::ShapeData& a, const io::ShapeData& b, const Pose* pose_b, const RunConfig& cfg);

/// Build one shape in a number type and count its features (the `info` verb).
ShapeCounts shape_counts(const io::ShapeData& s, NumberKind number, const Pose* pose = nullptr);

}  // namespace sepax::cli
