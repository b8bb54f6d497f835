# Build time (CI builds everything twice from scratch on 2 cores, docs/build.md):
# unity builds, on with CCM_UNITY_BUILD (scripts/test.sh and scripts/run.sh turn it on).
# A unity build compiles batches of a target's sources as one translation unit, so two .cpp
# files of one target that define the same name in an anonymous namespace (or as static) no
# longer compile together. Such a file is kept out of the batches next to its target:
#   set_source_files_properties(dir/file.cpp PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
# and a build with -DCCM_UNITY_BUILD=ON -DCCM_UNITY_BUILD_BATCH_SIZE=0 (every source of a target
# in one batch) finds every such pair at once.
set(CCM_UNITY_BUILD_BATCH_SIZE 8 CACHE STRING "Sources per unity batch (0: a whole target)")
set(CMAKE_UNITY_BUILD ${CCM_UNITY_BUILD})
set(CMAKE_UNITY_BUILD_BATCH_SIZE ${CCM_UNITY_BUILD_BATCH_SIZE})

# One precompiled header for the libraries: the headers most of their sources include, parsed once
# per build instead of once per translation unit. ccm_engine builds it; the other libraries reuse
# it (their extra compile definitions are not used by these headers). A source compiled with its
# own options sets SKIP_PRECOMPILE_HEADERS (engine/CMakeLists.txt).
set(CCM_LIBRARY_PCH_HEADERS <Eigen/Core> <Eigen/Geometry> <fmt/format.h> <algorithm> <array>
  <cmath> <filesystem> <map> <memory> <optional> <string> <string_view> <vector>)
function(ccm_library_pch target)
  if(target STREQUAL "ccm_engine")
    target_precompile_headers(ccm_engine PRIVATE ${CCM_LIBRARY_PCH_HEADERS})
  else()
    target_precompile_headers(${target} REUSE_FROM ccm_engine)
  endif()
endfunction()
