// sepax/hull/index.hpp
//
// as_index: the hull's int indices (point, triangle, face numbers, -1 for none) as container subscripts.
#pragma once

#include <cstddef>

namespace sepax::hull::detail {

/// A non-negative int index as a container subscript.
inline std::size_t as_index(int i) { return static_cast<std::size_t>(i); }

}  // namespace sepax::hull::detail
