#include <catch2/catch.hpp>

#include <set>

#include <sepax/contact_feature.hpp>

using namespace sepax;

TEST_CASE("contact feature ids: equality, swap, keys, names", "[contact_feature]") {
  const ContactFeatureId id{ShapeFeature::face(3), ShapeFeature::vertex(7)};
  CHECK(id == ContactFeatureId{ShapeFeature::face(3), ShapeFeature::vertex(7)});
  CHECK_FALSE(id == ContactFeatureId{ShapeFeature::face(3), ShapeFeature::vertex(8)});
  CHECK_FALSE(id == ContactFeatureId{ShapeFeature::edge(3), ShapeFeature::vertex(7)});
  CHECK(id.swapped() == ContactFeatureId{ShapeFeature::vertex(7), ShapeFeature::face(3)});
  CHECK(to_string(id) == "A:face 3/B:vertex 7");
  // keys are distinct for distinct ids
  std::set<std::uint64_t> keys;
  int n = 0;
  for (auto ka : {ShapeFeatureKind::Vertex, ShapeFeatureKind::Edge, ShapeFeatureKind::Face})
    for (auto kb : {ShapeFeatureKind::Vertex, ShapeFeatureKind::Edge, ShapeFeatureKind::Face})
      for (int i : {0, 1, 5, 1000000})
        for (int j : {0, 2, 5, 999999}) {
          keys.insert(ContactFeatureId{{ka, i}, {kb, j}}.key());
          ++n;
        }
  CHECK(static_cast<int>(keys.size()) == n);
}
