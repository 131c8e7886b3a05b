// python/src/tools.hpp
//
// The parts of the Python module that use the sepax program's and the
// fuzzer's libraries (sepax_cli_lib, sepax_fuzz_lib; built when both are
// configured, SEPAX_PYTHON_TOOLS): the SVG picture of a query, the fuzzer's
// full audit report, and the replay of a fuzzer reproducer.  No pybind11
// here: module.cpp converts to and from Python objects.
#pragma once

#include <cstdint>
#include <string>

#include <sepax/fuzz/case.hpp>
#include <sepax/fuzz/check.hpp>

#include "query_core.hpp"

namespace sepax::python {

/// The SVG document of src/render/svg_render.hpp for A and B at their poses
/// (drawn in world coordinates, moved in double) and the answer `q` of the
/// query on them (its verdict, feature, world axis and manifold points).
std::string render_query_svg(const ConvexPolyhedron<double>& a, const PoseD& pose_a,
                             const ConvexPolyhedron<double>& b, const PoseD& pose_b, const QueryOut& q,
                             const std::string& title);

struct AuditReport {
  std::string text;  // the text report, or the JSON object
  int status = 0;    // fuzz::run_audit: 0 no unexplained disagreement, 1 at least one
  int rounded = 0;   // coordinates that changed when rounded to float
};

/// fuzz::run_audit on A and B' = B posed into A's frame (in double), every
/// coordinate rounded to the nearest float (the audit compares float, double
/// and exact arithmetic on one float-valued input).  Throws InvalidInput when
/// a rounded shape is no longer a valid convex polyhedron.
AuditReport audit_report(const ConvexPolyhedron<double>& a, const PoseD& pose_a,
                         const ConvexPolyhedron<double>& b, const PoseD& pose_b, bool use_double, bool json);

struct Replayed {
  fuzz::FuzzCase c;
  fuzz::CaseReport r;
};

/// What `sepax fuzz --replay FILE` does for one file: read the case (or
/// decode a libFuzzer input when `bytes`) and check it
/// (fuzz::check_case_guarded).  Throws InvalidInput (Parse) naming the file
/// when it cannot be read or parsed.
Replayed replay_case(const std::string& path, bool bytes);

}  // namespace sepax::python
