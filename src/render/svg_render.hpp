// src/render/svg_render.hpp
//
// Draw a SAT case as an SVG picture, so that a person can look at a case
// instead of reading numbers:
//
//   left panel   the two shapes (A blue, B red) in an orthographic view looking
//                along the chosen axis tilted a little, the contact points and
//                the contact normal;
//   right panel  the Gauss maps of A and of -B overlaid on the unit sphere,
//                seen from outside along the chosen axis (so the axis is the
//                centre of the disc): face normals are dots, edges are great
//                arcs (the arc of a double-sided polygon's edge is a half great
//                circle through its outward edge direction), the Minkowski
//                edge-edge faces (arc crossings) are small diamonds, and the
//                chosen axis is a ring.  The far hemisphere is drawn faded.
//
// Everything here is for looking at: the geometry is converted to double.
#pragma once

#include <string>
#include <vector>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/sat_result.hpp>

namespace sepax::render {

struct SvgContact {
  Vec3<double> position;
  double depth = 0;  // separation (negative when penetrating)
};

struct SvgScene {
  const ConvexPolyhedron<double>* a = nullptr;
  const ConvexPolyhedron<double>* b = nullptr;
  SatResult<double> sat;
  std::vector<SvgContact> contacts;  // may be empty
  std::string title;                 // shown at the top
};

/// The whole SVG document.
std::string render_svg(const SvgScene& scene);

}  // namespace sepax::render
