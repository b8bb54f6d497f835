# Every dependency is a Debian package installed by scripts/install-deps.sh.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(fmt REQUIRED)
find_package(tomlplusplus REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
find_package(nlohmann_json 3 REQUIRED)  # ccm recommend --json
find_package(Gmsh REQUIRED)
find_package(NLopt CONFIG REQUIRED)  # libnlopt-dev: target NLopt::nlopt (C API, nlopt.h)
set(MPI_CXX_SKIP_MPICXX ON)
find_package(MPI REQUIRED COMPONENTS C CXX)
find_package(OpenMP REQUIRED COMPONENTS CXX)  # the compiler's own (libgomp): engine threads
# libmetis-dev ships no CMake package: the header and the library, as target METIS::METIS.
find_path(METIS_INCLUDE_DIR metis.h REQUIRED)
find_library(METIS_LIBRARY metis REQUIRED)
add_library(METIS::METIS UNKNOWN IMPORTED)
set_target_properties(METIS::METIS PROPERTIES IMPORTED_LOCATION ${METIS_LIBRARY}
  INTERFACE_INCLUDE_DIRECTORIES ${METIS_INCLUDE_DIR})
find_package(SQLite3 REQUIRED)
find_package(HDF5 REQUIRED COMPONENTS C)
if(CCM_BUILD_TESTS)
  find_package(Catch2 2 REQUIRED)
  find_package(LibXml2 REQUIRED)  # libxml2-dev: the field tests parse the XDMF output with it
endif()
