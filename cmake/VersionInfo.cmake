# Script mode (cmake -P), run on every build by the ccm_version_info target (study/CMakeLists.txt):
# writes OUTPUT from TEMPLATE with CCM_VERSION and the current git hash of SOURCE_DIR.
# configure_file leaves OUTPUT untouched when its text is unchanged, so a build at the same commit
# recompiles nothing, and a new commit recompiles this one file.
# Inputs: -DSOURCE_DIR= -DTEMPLATE= -DOUTPUT= -DCCM_VERSION=
execute_process(COMMAND git rev-parse --short=12 HEAD
  WORKING_DIRECTORY "${SOURCE_DIR}"
  OUTPUT_VARIABLE CCM_GIT_HASH OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT CCM_GIT_HASH)
  set(CCM_GIT_HASH "unknown")
endif()
configure_file("${TEMPLATE}" "${OUTPUT}" @ONLY)
