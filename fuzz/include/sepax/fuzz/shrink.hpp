// sepax/fuzz/shrink.hpp
//
// A deterministic shrinker for failing fuzz cases: given a case and a failure
// predicate ("does this case still show the same bug?"), shrink tries simpler
// cases in a fixed order and keeps a step only when the predicate still holds:
//   1. remove points (chunks, then single vertices; the rest re-hulled);
//   2. simplify the pose (A's centre on a coarse grid, A's and B's frames to
//      the identity, B's offset rounded to few bits);
//   3. round coordinates to the coarsest power-of-two grid that still fails.
// Every kept step makes the case strictly simpler, so shrinking ends even
// without a budget; the budget (steps, seconds) is ShrinkOptions.
// same_failure is the campaign's predicate; tests inject synthetic ones.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <sepax/fuzz/case.hpp>
#include <sepax/fuzz/check.hpp>

namespace sepax::fuzz {

struct ShrinkOptions {
  int max_steps = 300;      ///< predicate evaluations
  double max_seconds = 60;  ///< wall clock
};

struct ShrinkStats {
  int steps = 0;               ///< predicate evaluations
  int kept = 0;                ///< steps that kept a simpler case
  bool out_of_budget = false;  ///< stopped by max_steps or max_seconds, not by a round without progress
  double seconds = 0;
  std::vector<std::string> log;  ///< one line per kept step, e.g. "remove 4 vertices of A (12 -> 8)"
};

using FailurePredicate = std::function<bool(const FuzzCase&)>;

/// What the shrinker must preserve: the comparison, configuration and SAT of
/// an unexplained finding (e.g. feature / float_plain / gauss_map).
struct FailureSignature {
  std::string comparison, config, sat;
  std::string str() const { return comparison + " " + config + " " + sat; }
};

/// The signature of the report's first unexplained finding (empty when none).
FailureSignature signature_of(const CaseReport& r);
/// The report has an unexplained finding with this signature.
bool has_failure(const CaseReport& r, const FailureSignature& s);
/// Predicate: check_case_guarded(c) still shows an unexplained finding with signature s.
FailurePredicate same_failure(const FailureSignature& s, const CheckOptions& opt = {});

/// Shrink c under `fails` (which must hold on c; if it does not, c is returned
/// unchanged with stats->steps == 1).  The original is never modified.
///   1. remove points   delete vertices of A or of B and re-hull the rest
///                      (sepax::convex_hull<float>, so a solid may become a
///                      flat double-sided polygon); chunks first (halves,
///                      quarters, ...), then single vertices;
///   2. simplify pose   move the whole scene so that A's centre is on a coarse
///                      grid near the origin; rotate the whole scene so that A's
///                      frame (normal of its largest face, its longest edge) is
///                      the identity; rotate B about its centre so that B's frame
///                      is the identity (or A's frame); round B's offset from A
///                      to 1, 2, 3, 4, 6, 8, ... significant bits;
///   3. round coordinates   every coordinate of A (then B) to a power-of-two
///                      grid 2^(E - k) for k = 1, 2, 3, 4, 6, 8, 12, 16, 20, 24
///                      (2^E >= the largest coordinate magnitude): the coarsest
///                      that still fails;
///
/// a geometric step keeps the face lists when the moved shapes still validate
/// (a cheap check, not counted), and re-hulls the moved points otherwise.
/// A kept step must make the case strictly simpler -- fewer vertices, or
/// fewer significant bits over all coordinates -- except the two rotations,
/// which are kept at most once each (they may add bits that the rounding steps
/// then remove).  So no sequence of steps can cycle, and shrinking ends even
/// without a budget.  Rounds repeat
/// until one makes no progress or the budget is spent.
///
/// Budget: at most `max_steps` predicate evaluations (each a full check_case
/// in the campaign) and `max_seconds` of wall time.  The order of the steps is
/// fixed, so with the same step budget the result is the same on every run;
/// the time limit only cuts a run short (ShrinkStats::out_of_budget says so).
///
/// The campaign's predicate (same_failure) is "check_case_guarded still reports
/// an unexplained finding of the same comparison, configuration and SAT as the
/// original's first unexplained finding"; tests inject synthetic predicates.
FuzzCase shrink(const FuzzCase& c, const FailurePredicate& fails, const ShrinkOptions& opt = {},
                ShrinkStats* stats = nullptr);

/// "<dir>/<stem>-min.case" for a reproducer "<dir>/<stem>.case"; with out_dir
/// given, in out_dir instead.
std::string shrunk_path(const std::string& original_path, const std::string& out_dir = "");

/// Shrink a finding (c, its report r) under same_failure(signature_of(r)) and
/// write the shrunk case to `path`, with its findings, where it came from
/// (`origin`) and the shrink log as comments.  Returns false (and writes
/// nothing) when r has no unexplained finding.
bool write_shrunk_reproducer(const std::string& path, const std::string& origin, const FuzzCase& c,
                             const CaseReport& r, const ShrinkOptions& opt = {},
                             ShrinkStats* stats = nullptr);

}  // namespace sepax::fuzz
