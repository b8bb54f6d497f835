# Gmsh (Debian libgmsh-dev) ships neither a CMake config nor a .pc file.
# ccm does not link Gmsh: engine/mesh/gmsh_api.cpp loads it on first use (dlopen), by the soname
# read here from the library found (GMSH_SONAME, e.g. libgmsh.so.4.8). Gmsh::Gmsh carries the
# headers and the dynamic loader's library.
find_path(GMSH_INCLUDE_DIR gmsh.h)
find_library(GMSH_LIBRARY gmsh)
if(GMSH_LIBRARY AND NOT GMSH_SONAME)
  execute_process(COMMAND ${CMAKE_OBJDUMP} -p ${GMSH_LIBRARY} OUTPUT_VARIABLE _gmsh_dump
    ERROR_QUIET)
  if(_gmsh_dump MATCHES "SONAME +([^\n ]+)")
    set(GMSH_SONAME "${CMAKE_MATCH_1}" CACHE STRING "Gmsh's library, as ccm loads it")
  endif()
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Gmsh REQUIRED_VARS GMSH_LIBRARY GMSH_INCLUDE_DIR GMSH_SONAME)
if(Gmsh_FOUND AND NOT TARGET Gmsh::Gmsh)
  add_library(Gmsh::Gmsh INTERFACE IMPORTED)
  set_target_properties(Gmsh::Gmsh PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${GMSH_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${CMAKE_DL_LIBS}")
endif()
