// Uses the installed header-only core (sepax::sepax) in float: two unit cubes
// 2.5 apart along x are separated by 0.5 along +x.
#include <cstdio>

#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/shapes.hpp>

int main() {
  using namespace sepax;
  const auto a = shapes::cube<float>();
  std::vector<Vec3<float>> moved;
  for (const auto& v : a.vertices()) moved.push_back(Vec3<float>(v[0] + 2.5f, v[1], v[2]));
  const auto b = a.with_vertices(moved);
  const auto g = sat::gauss_map(a, b);
  const auto r = sat::brute_force(a, b);
  std::printf("float: overlap %d, separation %g, feature %s\n", int(g.overlap), g.separation_as_double(),
              to_string(g.feature).c_str());
  const bool ok =
      !g.overlap && g.separation_as_double() == 0.5 && g.axis[0] == 1.0f && g.feature == r.feature;
  return ok ? 0 : 1;
}
