// sepax/fuzz/cli.hpp
//
// What the `sepax audit` verb runs (its command line is parsed in
// src/commands/audit_command.cpp): every decision the SATs make for one case,
// in float (or double) against exact mpq arithmetic -- the four triple
// products of every edge pair with their exact signs, the Minkowski-face and
// parallel verdicts, every candidate axis with its separation, error bound
// and exact value, the features chosen by every configuration and SAT, the
// contact manifold float against exact, notes on what is degenerate -- then
// the full differential check of the case (check_case_guarded).  Text: a
// report for people; JSON (AuditOptions::json): one object, keys in order:
//   number, reference, shapes {A, B: vertices, edges, faces, flat, extent},
//   edge_pairs [{a, b, triple_products [{name, value, sign, exact_sign,
//   differs}], minkowski_face {value, exact}, parallel {value, exact}}],
//   axes [{axis, separation, exact_separation, difference, error_bound,
//   exact_zero}], flat_pair, chosen [{config, sat, overlap, feature,
//   feature_text, separation}], manifold {exact, value, comparison}, notes,
//   check {valid, unexplained, findings} ("value": the audited number type's
//   result, "exact": the mpq one).
#pragma once

#include <ostream>

#include "case.hpp"

namespace sepax::fuzz {

struct AuditOptions {
  bool use_double = false;    ///< audit double instead of float
  bool json = false;          ///< one JSON object instead of the text report
  bool inject_fault = false;  ///< CheckOptions::inject_fault (checks the checker)
};

/// Prints the audit of c to out.  Returns 0 when the differential check finds
/// no unexplained disagreement, 1 otherwise.  Throws InvalidInput when a shape
/// of c is not a valid convex polyhedron in float.
int run_audit(const FuzzCase& c, const AuditOptions& opt, std::ostream& out);

}  // namespace sepax::fuzz
