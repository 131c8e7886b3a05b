// Replays the seed corpus fuzz/corpus/*.case through the checking core: every
// case must be valid (files named invalid-*.case must be rejected) and show no
// unexplained disagreement.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>

#include <sepax/fuzz/check.hpp>

using namespace sepax::fuzz;

TEST_CASE("seed corpus replays without unexplained disagreements", "[fuzz][corpus]") {
  const std::filesystem::path dir = std::filesystem::path(SEPAX_SOURCE_DIR) / "fuzz" / "corpus";
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".case") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 8);
  for (const auto& f : files) {
    INFO(f.string());
    const FuzzCase c = read_case_file(f.string());
    const CaseReport r = check_case_guarded(c);
    if (f.filename().string().rfind("invalid-", 0) == 0) {
      CHECK_FALSE(r.valid);
      continue;
    }
    REQUIRE(r.valid);
    for (const auto& x : r.unexplained) UNSCOPED_INFO("[" << x.comparison << " " << x.config << " " << x.sat << "] " << x.detail);
    CHECK(r.unexplained_count == 0);
    CHECK(r.by_comparison.at("overlap").total() > 0);
  }
}
