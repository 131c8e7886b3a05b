// The exact reference of every pair: sepax's traversal SAT in mpq_class on A
// and the pre-posed B (the same float-valued vertices every pre-posed row
// gets), converted to double only at the end.
#pragma once

#include "workloads.hpp"

namespace bench {

/// Fills ref_overlap and ref_sep of every pair of the cell.
void compute_reference(Cell& c);

}  // namespace bench
