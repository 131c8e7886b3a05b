// src/commands/batch.hpp
//
// Batch queries: JSON lines in, JSON lines out.
//
// Input, one object per line (blank lines are skipped, other keys ignored):
//   {"id": 7, "a": [[x,y,z], ...], "b": [[x,y,z], ...]}
// "a" and "b" are point sets in one world frame; each is replaced by its
// convex hull built in the configured number type (sepax::convex_hull<T>).
// "id" must be a number or a string and is echoed exactly as written.
//
// Output, one line per non-blank input line, in input order:
//   {"id": 7, "overlap": false, "separation": 0.5,
//    "feature": {"type": "faceA", "a": 3, "b": 0}, "normal": [0, 0, 1]}
// or, for a line that cannot be processed (invalid JSON, a missing or
// malformed key, bad points, a hull that cannot be built):
//   {"id": 7, "error": "line 3: b: ..."}     (id null when it cannot be read)
// and the run goes on with the next line.
#pragma once

#include <cstddef>
#include <istream>
#include <ostream>
#include <string_view>

#include "commands/sat_runner.hpp"
#include "json/json.hpp"

namespace sepax::cli {

struct BatchSummary {
  std::size_t queries = 0;  // non-blank lines
  std::size_t errors = 0;   // lines answered with an error object
};

/// The output object for one input line (never throws for bad input).
/// line_number is used in error messages.
json::Value batch_line(std::string_view line, std::size_t line_number, const RunConfig& cfg);

/// Process every line of in, writing one output line per query to out.
BatchSummary run_batch(std::istream& in, std::ostream& out, const RunConfig& cfg);

}  // namespace sepax::cli
