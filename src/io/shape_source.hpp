// src/io/shape_source.hpp
//
// Resolving a shape argument of the command line to ShapeData:
//
//   cube                 the cube [-1,1]^3
//   box:HX,HY,HZ         axis-aligned box with half extents HX, HY, HZ (> 0)
//   tetra                regular tetrahedron (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1)
//   prism:N              regular N-gon prism around z, circumradius 1, z in [-1,1]
//   polygon:N            double-sided regular N-gon in z = 0, circumradius 1
//   triangle             double-sided triangle (0,0,0), (1,0,0), (0,1,0)
//   FILE.off             OFF face list
//   FILE.obj             OBJ face list
//   FILE.pts|.xyz|.txt   points file (hulled)
//
// Built-in names win over files of the same name; write ./cube for a file
// called "cube".  Built-ins are made by sepax/shapes.hpp in double and passed
// on as a face list.  Errors: InvalidInput naming the argument or FILE:LINE.
#pragma once

#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "io/shape_data.hpp"

namespace sepax::cli::io {

/// True when spec names a built-in shape (whether or not its parameters are valid).
bool is_builtin_shape(const std::string& spec);

/// The built-in shape spec as a face list (InvalidInput for bad parameters).
ShapeData builtin_shape(const std::string& spec);

/// A built-in shape, a file (by extension), hull:SPEC, or - (read from
/// standard_input; std::cin in the one-argument form).
ShapeData load_shape(const std::string& spec, std::istream& standard_input);
ShapeData load_shape(const std::string& spec);

/// The objects of an OBJ file of several objects, as `sepax info` lists them.
struct ObjectListing {
  /// One object of the file: its name ("" when it has none) and its size in the file.
  struct Entry {
    std::string name;          ///< the `o` (else `g`) name; "" for faces before any
    std::size_t vertices = 0;  ///< vertices its faces use
    std::size_t faces = 0;     ///< faces as written in the file
  };
  std::string spec;            ///< the shape argument as given
  std::vector<Entry> objects;  ///< in file order; the index is the `FILE.obj#K` selector

  /// A header line and one line per object (index, name, counts).
  std::string text() const;
};

/// For an OBJ file of several objects, its objects (for `sepax info`);
/// nullopt for any other shape argument.  When spec is an OBJ file of one
/// object and `single` is given, that object is stored there, so that the
/// file is read once.
std::optional<ObjectListing> object_listing(const std::string& spec,
                                            std::optional<ShapeData>* single = nullptr);

/// One line per built-in, for --help.
const char* builtin_shapes_help();

}  // namespace sepax::cli::io
