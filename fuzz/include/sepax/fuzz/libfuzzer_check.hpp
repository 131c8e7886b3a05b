// sepax/fuzz/libfuzzer_check.hpp
//
// What every libFuzzer target does with its decoded case: the checking core
// with budgets that keep an input fast under the sanitizers, and an abort on
// an unexplained disagreement (its findings on stderr first), so that the
// engine keeps the input as a crash.
#pragma once

#include <cstdio>
#include <cstdlib>

#include <sepax/fuzz/check.hpp>

namespace sepax::fuzz {

inline void check_or_abort(const FuzzCase& c) {
  CheckOptions opt;
  opt.exact_brute_budget = 50'000;
  const CaseReport r = check_case_guarded(c, opt);
  if (r.unexplained_count > 0) {
    for (const auto& f : r.unexplained)
      std::fprintf(stderr, "[%s %s %s] %s\n", f.comparison.c_str(), f.config.c_str(), f.sat.c_str(),
                   f.detail.c_str());
    std::abort();
  }
}

}  // namespace sepax::fuzz
