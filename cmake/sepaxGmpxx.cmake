# sepax::gmpxx -- the GMP C++ bindings (libgmpxx, gmpxx.h) as an imported
# target, found on the machine where it is used.  Included by the build
# (CMakeLists.txt) and by the installed sepaxConfig.cmake, so the exported
# sepax::robust links the *name* sepax::gmpxx, never a library path of the
# machine sepax was built on: the install stays relocatable.
# Where: CMAKE_PREFIX_PATH, or set the cache variables SEPAX_GMPXX_LIBRARY
# and SEPAX_GMPXX_INCLUDE_DIR.
if(NOT TARGET sepax::gmpxx)
  find_library(SEPAX_GMPXX_LIBRARY NAMES gmpxx)
  find_path(SEPAX_GMPXX_INCLUDE_DIR NAMES gmpxx.h)
  mark_as_advanced(SEPAX_GMPXX_LIBRARY SEPAX_GMPXX_INCLUDE_DIR)
  if(SEPAX_GMPXX_LIBRARY AND SEPAX_GMPXX_INCLUDE_DIR)
    add_library(sepax::gmpxx UNKNOWN IMPORTED)
    set_target_properties(sepax::gmpxx PROPERTIES
      IMPORTED_LOCATION "${SEPAX_GMPXX_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${SEPAX_GMPXX_INCLUDE_DIR}")
  endif()
endif()
