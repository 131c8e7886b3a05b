// Posed queries, warm sequences and speculative margins in the checking core
// (check_posed.hpp, check.cpp's margin comparison): every comparison is made
// on generated cases, none is unexplained, and a comparison that is skipped
// above its budget is counted.
#include <catch2/catch.hpp>

#include <sepax/fuzz/check.hpp>
#include <sepax/fuzz/generators.hpp>
#include <sepax/fuzz/random.hpp>

using namespace sepax::fuzz;

TEST_CASE("posed, warm and margin comparisons run on every family and explain everything", "[fuzz][posed]") {
  std::map<std::string, Counts> by;
  for (const char* fam : {"boxes", "tetra", "flat", "touching", "prisms", "perturbed"}) {
    for (std::uint64_t i = 0; i < 2; ++i) {
      const FuzzCase c = generate(fam, case_seed(7, i));
      const CaseReport r = check_case_guarded(c);
      if (!r.valid) continue;
      for (const auto& x : r.unexplained)
        UNSCOPED_INFO(fam << " " << i << ": [" << x.comparison << " " << x.config << " " << x.sat << "] "
                          << x.detail);
      CHECK(r.unexplained_count == 0);
      for (const auto& [k, n] : r.by_config) by[k] += n;
    }
  }
  for (const char* cfg : {"float_plain", "double_plain", "float_robust", "double_robust"}) {
    INFO(cfg);
    CHECK(by["posed/" + std::string(cfg)][Classification::agree] > 0);
    CHECK(by["warm/" + std::string(cfg)][Classification::agree] > 0);
    CHECK(by["margin/" + std::string(cfg)].total() > 0);
  }
  // robust: exact decisions on the posed input, and exact rational poses
  CHECK(by["posed_exact/float_robust"][Classification::agree] > 0);
  CHECK(by["posed_exact/double_robust"][Classification::agree] > 0);
  CHECK(by["posed_rational/mpq"][Classification::agree] > 0);
  // robust margins decide exactly: never merely explained
  CHECK(by["margin/float_robust"][Classification::explained] == 0);
  CHECK(by["margin/double_robust"][Classification::explained] == 0);
}

TEST_CASE("posed comparisons: budgets skip and count, the option turns them off", "[fuzz][posed]") {
  const FuzzCase c = generate("boxes", case_seed(3, 0));
  CheckOptions none;
  none.posed_exact_pair_budget = 0;
  const CaseReport r = check_case_guarded(c, none);
  REQUIRE(r.valid);
  CHECK(r.skipped.count("posed_exact/float_robust/gauss_map") == 1);
  CHECK(r.skipped.count("posed_rational/mpq/traversal") == 1);
  CHECK(r.by_comparison.count("posed_exact") == 0);
  CHECK(r.by_comparison.at("posed").total() > 0);
  CheckOptions off;
  off.posed = false;
  off.margins = false;
  const CaseReport q = check_case_guarded(c, off);
  CHECK(q.by_comparison.count("posed") == 0);
  CHECK(q.by_comparison.count("warm") == 0);
  CHECK(q.by_comparison.count("margin") == 0);
}
