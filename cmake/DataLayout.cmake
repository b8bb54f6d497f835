# Where ccm's data sits, in the build tree and under an install prefix, laid out alike:
#   <prefix>/bin/ccm                       the executable
#   <prefix>/share/ccm/rig/                cases.toml, geometry.toml (the rig's case and geometry files)
#   <prefix>/share/ccm/scenes/             example scenes and grid files
#   <prefix>/share/ccm/reference/          the reference store `ccm recommend` reads by default
#   <prefix>/share/ccm/examples/rig-dev/   the synthetic measured trials (docs/measurements.md)
#   <prefix>/share/doc/ccm/                README.md and docs/ (as in the sources, so its links work)
# The executable finds share/ccm relative to itself (app/data_paths.hpp): CCM_DATA_DIR_FROM_BINDIR
# is the relative path from the bin folder to the data root, never an absolute one, so an installed
# prefix can be moved. The build tree gets <build>/share/ccm with links into the source tree, so
# <build>/ccm reads the sources' files as they are edited.
include(GNUInstallDirs)

function(ccm_data_layout target)
  file(RELATIVE_PATH data_from_bin ${CMAKE_INSTALL_FULL_BINDIR} ${CMAKE_INSTALL_FULL_DATADIR})
  target_compile_definitions(${target} PRIVATE CCM_DATA_DIR_FROM_BINDIR="${data_from_bin}")

  set(build_data ${PROJECT_BINARY_DIR}/share/ccm)
  file(MAKE_DIRECTORY ${build_data}/rig ${build_data}/examples)
  foreach(name cases.toml geometry.toml)
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/rig_models/${name} ${build_data}/rig/${name} SYMBOLIC)
  endforeach()
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/scenes ${build_data}/scenes SYMBOLIC)
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/data/reference ${build_data}/reference SYMBOLIC)
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/tests/data/rig-dev ${build_data}/examples/rig-dev SYMBOLIC)
endfunction()

install(TARGETS ccm RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${PROJECT_SOURCE_DIR}/rig_models/cases.toml ${PROJECT_SOURCE_DIR}/rig_models/geometry.toml
  DESTINATION ${CMAKE_INSTALL_DATADIR}/ccm/rig)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/ccm/scenes)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/reference/
  DESTINATION ${CMAKE_INSTALL_DATADIR}/ccm/reference)  # the reference store (docs/recommendation.md)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/tests/data/rig-dev/
  DESTINATION ${CMAKE_INSTALL_DATADIR}/ccm/examples/rig-dev)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)  # README.md links docs/...
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
