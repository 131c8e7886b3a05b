// The fuzzer's contact-manifold comparison (fuzz/src/check_manifold.cpp).
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <sstream>

#include <sepax/fuzz/campaign.hpp>
#include <sepax/fuzz/case.hpp>
#include <sepax/fuzz/check_manifold.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/shapes.hpp>

using namespace sepax;
using namespace sepax::fuzz;
using Q = mpq_class;

namespace {
std::vector<std::string> corpus_files() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(std::string(SEPAX_SOURCE_DIR) + "/fuzz/corpus"))
    if (e.path().extension() == ".case" && e.path().filename().string().rfind("invalid", 0) != 0)
      out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

// Two unit cubes with crossed edges (an edge contact), float coordinates.
std::pair<ConvexPolyhedron<float>, ConvexPolyhedron<float>> crossed_cubes() {
  auto moved = [](const ConvexPolyhedron<float>& p, const Eigen::Matrix3f& R, const Vec3<float>& t) {
    std::vector<Vec3<float>> vs;
    for (const auto& v : p.vertices()) vs.push_back(R * v + t);
    return p.with_vertices(vs);
  };
  const float c = 0.70710677f;
  Eigen::Matrix3f rx, ry;
  rx << 1, 0, 0, 0, c, -c, 0, c, c;
  ry << c, 0, c, 0, 1, 0, -c, 0, c;
  const auto a = moved(shapes::cube<float>(1.0), rx, Vec3<float>(0, 0, 0));
  const auto b = moved(shapes::cube<float>(1.0), ry, Vec3<float>(0.1f, -0.2f, 2.7284271f));
  return {a, b};
}
}  // namespace

TEST_CASE("manifold comparison on the corpus: compared, nothing unexplained, bounds not vacuous",
          "[fuzz][manifold]") {
  Counts total;
  std::map<std::string, Counts> details;
  double max_depth = 0, max_pos = 0;
  for (const auto& f : corpus_files()) {
    INFO(f);
    const CaseReport r = check_case(read_case_file(f));
    REQUIRE(r.valid);
    for (const auto& x : r.unexplained)
      UNSCOPED_INFO("[" << x.comparison << " " << x.config << "] " << x.detail);
    CHECK(r.unexplained_count == 0);
    const auto it = r.by_comparison.find("manifold");
    REQUIRE(it != r.by_comparison.end());
    total += it->second;
    for (const auto& [k, c] : r.details) details[k] += c;
    if (r.maxima.count("manifold.depth")) max_depth = std::max(max_depth, r.maxima.at("manifold.depth"));
    if (r.maxima.count("manifold.position")) max_pos = std::max(max_pos, r.maxima.at("manifold.position"));
  }
  CHECK(total[Classification::unexplained] == 0);
  CHECK(total[Classification::agree] >= 80);
  CHECK(total[Classification::exact_zero] >= 1);  // 28-touching-float-support-fallback
  CHECK(details["manifold.points"].total() > 0);
  CHECK(details["manifold.depth_position"].total() > 0);
  CHECK(details["manifold.reduction"].total() > 0);
  CHECK(details["manifold.support_fallback"][Classification::exact_zero] >= 1);
  // every compared depth and position was within its bound, and the bounds
  // are not absurdly loose on these cases
  CHECK(max_depth <= 1.0);
  CHECK(max_pos <= 1.0);
  CHECK(max_depth >= 1e-4);
  CHECK(max_pos >= 1e-4);
}

TEST_CASE("float loses the clipped point of an exact touching contact: exact_zero, not agree",
          "[fuzz][manifold]") {
  const CaseReport r = check_case(
      read_case_file(std::string(SEPAX_SOURCE_DIR) + "/fuzz/corpus/28-touching-float-support-fallback.case"));
  REQUIRE(r.valid);
  CHECK(r.unexplained_count == 0);
  CHECK(r.by_config.at("manifold/float_robust")[Classification::exact_zero] == 1);
  CHECK(r.by_config.at("manifold/gmpq")[Classification::agree] == 1);
}

TEST_CASE("edge contact: agrees, and a float depth off by more than its bound is unexplained",
          "[fuzz][manifold]") {
  const auto [a, b] = crossed_cubes();
  const auto aq = ConvexPolyhedron<Q>::convert_from(a), bq = ConvexPolyhedron<Q>::convert_from(b);
  const auto rq = sat::gauss_map(aq, bq);
  auto rf = sat::gauss_map(a, b);
  REQUIRE(rf.feature.type == FeatureType::EdgePair);
  REQUIRE(rf.feature == rq.feature);
  {
    CaseReport rep;
    CHECK(check_manifold_float(a, b, aq, bq, rq, rf, CheckOptions{}, rep) == Classification::agree);
    CHECK(rep.unexplained.empty());
    CHECK(rep.details["manifold.position"][Classification::agree] == 1);
    CHECK(rep.details["manifold.depth"][Classification::agree] == 1);
  }
  // one float ulp at the depth's magnitude is within the bound ...
  {
    auto r2 = rf;
    r2.separation.num = std::nextafter(r2.separation.num, 1.0f);
    CaseReport rep;
    CHECK(check_manifold_float(a, b, aq, bq, rq, r2, CheckOptions{}, rep) == Classification::agree);
  }
  // ... 1e-3 is not
  {
    auto r2 = rf;
    r2.separation.num += 1e-3f;
    CaseReport rep;
    CHECK(check_manifold_float(a, b, aq, bq, rq, r2, CheckOptions{}, rep) == Classification::unexplained);
    REQUIRE(rep.unexplained.size() == 1);
    CHECK(rep.unexplained[0].comparison == "manifold");
    CHECK(rep.unexplained[0].detail.find("depth") != std::string::npos);
    CHECK(rep.by_config["manifold/float_given"][Classification::unexplained] == 1);
  }
}

TEST_CASE("face contacts at every scale: the clip replay welds as contact_manifold does",
          "[fuzz][manifold]") {
  // (a squared weld tolerance leaves float's range beyond about 1e19 and below 1e-19: contact_manifold
  // and the replay compare squared lengths in units of a power of two near the extent)
  for (const double s : {1e-30, 1e-20, 1.0, 1e24, 1e30}) {
    INFO("scale " << s);
    const auto a = shapes::box<float>(s, s, s);
    std::vector<Vec3<float>> moved;
    for (const auto& v : a.vertices())
      moved.push_back(Vec3<float>(v + Vec3<float>(float(1.9 * s), float(0.3 * s), 0)));
    const auto b = a.with_vertices(moved);
    const auto aq = ConvexPolyhedron<Q>::convert_from(a), bq = ConvexPolyhedron<Q>::convert_from(b);
    const auto rq = sat::gauss_map(aq, bq);
    const auto rf = sat::gauss_map(a, b);
    REQUIRE(rf.feature == rq.feature);
    CaseReport rep;
    CHECK(check_manifold_float(a, b, aq, bq, rq, rf, CheckOptions{}, rep) == Classification::agree);
    CHECK(rep.unexplained.empty());
    CHECK(rep.details["manifold.points"][Classification::agree] == 1);
    CHECK(rep.details["manifold.depth_position"][Classification::agree] == 1);
  }
}

TEST_CASE("a float SAT feature other than the exact one is not compared", "[fuzz][manifold]") {
  const auto a = shapes::cube<float>(1.0);
  const auto small = shapes::cube<float>(0.5);
  std::vector<Vec3<float>> vs;
  for (const auto& v : small.vertices()) vs.push_back(v + Vec3<float>(0.1f, 0.2f, 1.4f));
  const auto b = small.with_vertices(vs);
  const auto aq = ConvexPolyhedron<Q>::convert_from(a), bq = ConvexPolyhedron<Q>::convert_from(b);
  const auto rq = sat::gauss_map(aq, bq);
  auto rf = sat::gauss_map(a, b);
  REQUIRE(rf.feature == rq.feature);
  CaseReport rep;
  CHECK(check_manifold_float(a, b, aq, bq, rq, rf, CheckOptions{}, rep) == Classification::agree);
  CHECK(rep.by_comparison["manifold"][Classification::agree] == 1);
  CHECK(rep.details["manifold.points"][Classification::agree] == 1);
  rf.feature.b = (rf.feature.b + 1) % b.vertex_count();
  CaseReport rep2;
  CHECK(check_manifold_float(a, b, aq, bq, rq, rf, CheckOptions{}, rep2) == Classification::agree);
  CHECK(rep2.by_comparison["manifold"].total() == 0);
  CHECK(rep2.details["manifold.skipped_feature_differs"].total() == 1);
}

TEST_CASE("the report: manifold table and the --json 'manifold' key", "[fuzz][manifold]") {
  Report rep;
  rep.add("corpus", check_case(read_case_file(std::string(SEPAX_SOURCE_DIR) +
                                              "/fuzz/corpus/08-box-on-box-touching.case")));
  std::ostringstream js, tx;
  print_json(js, rep);
  print_text(tx, rep);
  CHECK(js.str().find("\"manifold\":{\"classes\":{\"agree\":") != std::string::npos);
  CHECK(js.str().find("\"aspects\":{") != std::string::npos);
  CHECK(js.str().find("\"max_error_over_bound\":{") != std::string::npos);
  CHECK(tx.str().find("contact manifold (float vs exact)") != std::string::npos);
  CHECK(tx.str().find("manifold/float_plain") != std::string::npos);
}
