// src/commands/render_command.hpp
//
// The picture behind `sepax render A B --svg FILE`: both shapes, the contact
// manifold, and the overlaid Gauss maps of A and -B with the Minkowski
// edge-edge faces and the chosen axis (src/render/svg_render.hpp).  The case
// is computed in double (with the robust policy when cfg.robust), whatever
// cfg.number says: the picture is for looking at, and its feature indices
// then match `sepax query --number double` on the same arguments.
#pragma once

#include <string>

#include "commands/pose.hpp"
#include "commands/sat_runner.hpp"
#include "io/shape_data.hpp"

namespace sepax::cli {

/// The SVG document.  Throws InvalidInput for bad shapes.
std::string render_case_svg(const io::ShapeData& a, const io::ShapeData& b, const Pose* pose_b,
                            const RunConfig& cfg, const std::string& title);

}  // namespace sepax::cli
