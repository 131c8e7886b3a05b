// Precompiled header shared by the test executables that instantiate sepax
// with CGAL's exact number types (compiling CGAL is the slow part).
#pragma once
#include <catch2/catch.hpp>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <sepax/robust/number_types.hpp>
