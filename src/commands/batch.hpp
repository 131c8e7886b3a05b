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
//    "feature": {"type": "faceA", "a": 3, "b": 0}, "normal": [0, 0, 1],
//    "manifold": {"kind": "face", ..., "points": [...]}}
// ("manifold" as in `query --json`, query_output.hpp; left out with
// BatchOptions::manifold false), or, for a line that cannot be processed
// (invalid JSON, a missing or malformed key, bad points, a hull that cannot
// be built):
//   {"id": 7, "error": "line 3: b: ..."}     (id null when it cannot be read)
// and the run goes on with the next line.
//
// With BatchOptions::jobs > 1 the lines are answered by that many threads;
// the output is the same, line for line, as with one (each line is answered
// on its own, and the lines are written in input order as soon as every
// earlier line is written).
#pragma once

#include <cstddef>
#include <istream>
#include <ostream>
#include <string>
#include <string_view>

#include "commands/sat_runner.hpp"

namespace sepax::cli {

struct BatchOptions {
  RunConfig cfg;
  bool manifold = true;  // the contact manifold in every answer
  int jobs = 1;          // threads; 0: one per core
};

struct BatchSummary {
  std::size_t queries = 0;  // non-blank lines
  std::size_t errors = 0;   // lines answered with an error object
};

struct BatchAnswer {
  std::string text;    // the output line, without the newline
  bool error = false;  // an error object
};

/// The answer to one input line (never throws for bad input).  line_number
/// is used in error messages.
BatchAnswer batch_line(std::string_view line, std::size_t line_number, const BatchOptions& opt);

/// Process every line of in, writing one output line per query to out.
BatchSummary run_batch(std::istream& in, std::ostream& out, const BatchOptions& opt);

/// The number of threads `jobs` means (0: the number of cores, at least 1).
int batch_threads(int jobs);

}  // namespace sepax::cli
