// src/commands/sat_runner.cpp -- see sat_runner.hpp.
#include "commands/sat_runner.hpp"

#include <cmath>
#include <stdexcept>

#include <gmpxx.h>

#include <sepax/contact_manifold.hpp>
#include <sepax/robust/number_types.hpp>
#include <sepax/sat.hpp>

#include "commands/shape_builder.hpp"

#if __has_include(<sepax/sat_traversal.hpp>)
#include <sepax/sat_traversal.hpp>
#define SEPAX_CLI_HAVE_TRAVERSAL 1
#else
#define SEPAX_CLI_HAVE_TRAVERSAL 0
#endif

#if __has_include(<sepax/robust/robust_kernel.hpp>)
#include <sepax/robust/robust_kernel.hpp>
#define SEPAX_CLI_HAVE_ROBUST 1
#else
#define SEPAX_CLI_HAVE_ROBUST 0
#endif

namespace sepax::cli {

const char* name(NumberKind k) {
  switch (k) {
    case NumberKind::Float:
      return "float";
    case NumberKind::Double:
      return "double";
    case NumberKind::Exact:
      return "exact";
  }
  return "?";
}

const char* name(AlgorithmKind k) {
  switch (k) {
    case AlgorithmKind::Brute:
      return "brute";
    case AlgorithmKind::Gauss:
      return "gauss";
    case AlgorithmKind::Traversal:
      return "traversal";
  }
  return "?";
}

SatAlgorithm sat_algorithm(AlgorithmKind k) {
  switch (k) {
    case AlgorithmKind::Brute:
      return SatAlgorithm::brute_force;
    case AlgorithmKind::Gauss:
      return SatAlgorithm::gauss_map;
    case AlgorithmKind::Traversal:
      return SatAlgorithm::traversal;
  }
  return SatAlgorithm::gauss_map;
}

std::optional<NumberKind> parse_number_kind(std::string_view s) {
  if (s == "float") return NumberKind::Float;
  if (s == "double") return NumberKind::Double;
  if (s == "exact") return NumberKind::Exact;
  return std::nullopt;
}

std::optional<AlgorithmKind> parse_algorithm_kind(std::string_view s) {
  if (s == "brute") return AlgorithmKind::Brute;
  if (s == "gauss") return AlgorithmKind::Gauss;
  if (s == "traversal") return AlgorithmKind::Traversal;
  return std::nullopt;
}

bool traversal_available() { return SEPAX_CLI_HAVE_TRAVERSAL != 0; }
bool robust_available() { return SEPAX_CLI_HAVE_ROBUST != 0; }
bool hull_builder_available() { return kHullAvailable; }

std::string unsupported_reason(const RunConfig& cfg) {
  if (cfg.algorithm == AlgorithmKind::Traversal && !traversal_available()) {
    return "--algorithm traversal: this build has no traversal SAT (sepax/sat_traversal.hpp)";
  }
  if (cfg.robust && cfg.number == NumberKind::Exact) {
    return "--robust applies to --number float or double (exact arithmetic needs no robust policy)";
  }
  if (cfg.robust && !robust_available()) {
    return "--robust: this build has no robust policy (sepax/robust/robust_kernel.hpp)";
  }
  return {};
}

namespace {

template <Number T>
ShapeCounts counts_of(const ConvexPolyhedron<T>& p) {
  return ShapeCounts{p.vertex_count(), p.edge_count(), p.face_count(), p.is_flat()};
}

/// The manifold of shapes built at their coordinates minus centre, with the
/// positions back in world coordinates.
template <Number T>
ManifoldOut manifold_out(const ContactManifold<T>& m, const Vec3<T>& centre) {
  ManifoldOut out;
  out.kind = to_string(m.kind);
  out.reference_shape = m.reference_shape;
  out.reference_face = m.reference_face;
  out.incident_face = m.incident_face;
  out.candidate_points = m.candidate_points;
  for (const auto& p : m.points) {
    out.points.push_back(ContactOut{Vec3<double>(vec_to_double(p.position) + vec_to_double(centre)),
                                    sepax::to_double(p.separation), to_string(p.id)});
  }
  return out;
}

template <class Policy, Number T>
SatResult<T> run_algorithm(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b, AlgorithmKind alg) {
  return sat::run<Policy>(sat_algorithm(alg), a, b);
}

template <Number T>
RunOutcome run_typed(const io::ShapeData& sa, const io::ShapeData& sb, const Pose* pose_b,
                     const RunConfig& cfg) {
  // Both shapes in one frame near them (shape_builder.hpp, build_pair), so
  // a small pair far from the origin is resolved as well as near it;
  // positions are reported in world coordinates.
  const BuiltPair<T> pair = build_pair<T>(sa, sb, pose_b);
  const ConvexPolyhedron<T>& a = pair.a;
  const ConvexPolyhedron<T>& b = pair.b;
  SatResult<T> r;
  if (cfg.robust) {
#if SEPAX_CLI_HAVE_ROBUST
    if constexpr (!number_traits<T>::is_exact) {
      r = run_algorithm<policy::Robust>(a, b, cfg.algorithm);
    } else {
      throw std::invalid_argument(unsupported_reason(cfg));
    }
#else
    throw std::invalid_argument(unsupported_reason(cfg));
#endif
  } else {
    r = run_algorithm<policy::Plain>(a, b, cfg.algorithm);
  }
  RunOutcome out;
  out.overlap = r.overlap;
  out.separation = r.separation_as_double();
  out.feature = r.feature;
  out.stats = r.stats;
  out.early_out = r.early_out;
  out.normal = unit_as_double(r.axis);
  out.a = counts_of(a);
  out.b = counts_of(b);
  out.manifold = manifold_out(contact_manifold(a, b, r), pair.origin);
  return out;
}

}  // namespace

RunOutcome run_sat(const io::ShapeData& a, const io::ShapeData& b, const Pose* pose_b, const RunConfig& cfg) {
  if (const std::string why = unsupported_reason(cfg); !why.empty()) throw std::invalid_argument(why);
  switch (cfg.number) {
    case NumberKind::Float:
      return run_typed<float>(a, b, pose_b, cfg);
    case NumberKind::Double:
      return run_typed<double>(a, b, pose_b, cfg);
    case NumberKind::Exact:
      return run_typed<mpq_class>(a, b, pose_b, cfg);
  }
  throw std::invalid_argument("unknown number type");
}

namespace {
template <Number T>
ShapeCounts counts_centred(const io::ShapeData& s, const Pose* pose) {
  const std::vector<Vec3<T>> world[] = {shape_points<T>(s, pose)};
  const Vec3<T> centre = io::exact_centre<T>(world);
  return counts_of(build_shape<T>(s, pose, &centre));
}
}  // namespace

ShapeCounts shape_counts(const io::ShapeData& s, NumberKind number, const Pose* pose) {
  switch (number) {
    case NumberKind::Float:
      return counts_centred<float>(s, pose);
    case NumberKind::Double:
      return counts_centred<double>(s, pose);
    case NumberKind::Exact:
      return counts_centred<mpq_class>(s, pose);
  }
  throw std::invalid_argument("unknown number type");
}

}  // namespace sepax::cli
