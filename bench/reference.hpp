// The exact references of every pair, sepax's traversal SAT in mpq_class
// converted to double only at the end:
//   * pre-posed rows: on A and the pre-posed B (the same float-valued vertices
//     every pre-posed row gets);
//   * posed rows: on A and posed(B, relative_pose(pose_a, pose_b)), the input
//     a posed query decides on (posing.hpp).  The peers' posed rows are judged
//     against it too: they get the same float poses.
#pragma once

#include "workloads.hpp"

namespace bench {

/// Fills the references of every pair of the cell.
void compute_reference(Cell& c);

}  // namespace bench
