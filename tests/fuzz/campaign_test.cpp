// A short standalone campaign (a few cases of every family) and its report.
// The command lines of `sepax fuzz` and `sepax audit`: tests/cli/fuzz_command_test.cpp.
#include <catch2/catch.hpp>

#include <sstream>

#include <sepax/fuzz/campaign.hpp>
#include <sepax/fuzz/generators.hpp>
#include <sepax/robust/number_types.hpp>
#include <sepax/sat_gauss_map.hpp>

using namespace sepax::fuzz;

TEST_CASE("short campaign over every family: no unexplained disagreement", "[fuzz][campaign]") {
  Report rep;
  for (const auto& fam : family_names()) {
    for (std::uint64_t seed = 100; seed < 103; ++seed) {
      const FuzzCase c = generate(fam, seed);
      const CaseReport r = check_case_guarded(c);
      for (const auto& x : r.unexplained)
        UNSCOPED_INFO(fam << " seed " << seed << ": [" << x.comparison << " " << x.config << " " << x.sat
                          << "] " << x.detail);
      CHECK(r.unexplained_count == 0);
      rep.add(fam, r);
    }
  }
  CHECK(rep.cases > 0);
  CHECK(rep.families.size() == family_names().size());
  // every comparison was exercised
  for (const char* k : {"arc_sign", "minkowski_face", "overlap", "feature", "separation", "exact"})
    CHECK(rep.comparisons[k].total() > 0);
  CHECK(rep.unexplained() == 0);
}

TEST_CASE("touching family: face contacts are exact contacts", "[fuzz][campaign]") {
  // Face-contact placements (2 in 3) must survive the float conversion: the
  // exact maximum separation is exactly zero.  Edge contacts may overlap.
  int zero = 0, total = 0;
  for (std::uint64_t seed = 0; seed < 24; ++seed) {
    const FuzzCase c = generate("touching", seed);
    auto build = [](const ShapeSpec& s) {
      std::vector<sepax::Vec3<mpq_class>> v;
      for (const auto& p : s.vertices) v.push_back(sepax::vec_from_double<mpq_class>(p));
      return sepax::ConvexPolyhedron<mpq_class>::from_faces(std::move(v), s.faces);
    };
    const auto a = build(c.a), b = build(c.b);
    const auto r = sepax::sat::gauss_map(a, b);
    ++total;
    zero += sepax::sign(r.separation) == 0;
    CHECK(sepax::sign(r.separation) <= 0);  // contact point is shared: never separated
  }
  CHECK(zero * 2 >= total);
}

TEST_CASE("comparisons skipped above size budgets are counted and reported", "[fuzz][campaign][skips]") {
  const FuzzCase c = generate("boxes", 3);
  // default budgets: a box pair runs everything
  const CaseReport full = check_case_guarded(c);
  REQUIRE(full.valid);
  CHECK(full.skipped.empty());
  // zero budgets: every budgeted run is skipped, and each skip is counted
  CheckOptions none;
  none.exact_brute_budget = 0;
  none.exact_gauss_pair_budget = 0;
  none.gmpq_pair_budget = 0;
  none.float_brute_budget = 0;
  const CaseReport r = check_case_guarded(c, none);
  REQUIRE(r.valid);
  for (const char* key :
       {"exact/mpq/brute_force", "exact/gmpq/brute_force", "exact/gmpq/gauss_map", "exact/gmpq/traversal",
        "exact/epeck/brute_force", "exact/epeck/gauss_map", "overlap/float_plain/brute_force",
        "feature/double_plain/brute_force", "separation/float_robust/brute_force"}) {
    INFO(key);
    CHECK(r.skipped.count(key) == 1);
  }
  // nothing skipped is also counted as compared
  CHECK(r.by_config.count("exact/gmpq") == 0);
  CHECK(r.by_comparison.at("overlap").total() < full.by_comparison.at("overlap").total());
  Report rep;
  rep.add("boxes", r);
  rep.add("boxes", r);
  CHECK(rep.skipped.at("exact/gmpq/gauss_map") == 2);
  CHECK(rep.families.at("boxes").skipped.at("overlap/float_plain/brute_force") == 2);
  CHECK(rep.skipped_total() == 2 * static_cast<std::int64_t>(r.skipped.size()));
  std::ostringstream js, txt;
  print_json(js, rep);
  print_text(txt, rep);
  CHECK(js.str().find("\"skipped\":{\"exact/epeck/brute_force\":2") != std::string::npos);
  CHECK(js.str().find("\"skipped_total\":") != std::string::npos);
  CHECK(txt.str().find("skipped above size budgets (not compared): " + std::to_string(rep.skipped_total())) !=
        std::string::npos);
  CHECK(txt.str().find("(boxes 2)") != std::string::npos);
}
