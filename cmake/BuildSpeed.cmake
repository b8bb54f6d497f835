# Build time (CI builds everything twice from scratch on 2 cores, docs/build.md):
# unity builds, on with CCM_UNITY_BUILD (scripts/test.sh and scripts/run.sh turn it on).
# A unity build compiles batches of a target's sources as one translation unit, so two .cpp
# files of one target that define the same name in an anonymous namespace (or as static) no
# longer compile together. Such a file is kept out of the batches next to its target:
#   set_source_files_properties(dir/file.cpp PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
# and a build with -DCCM_UNITY_BUILD=ON -DCCM_UNITY_BUILD_BATCH_SIZE=0 (every source of a target
# in one batch) finds every such pair at once.
set(CCM_UNITY_BUILD_BATCH_SIZE 16 CACHE STRING "Sources per unity batch (0: a whole target)")
set(CMAKE_UNITY_BUILD ${CCM_UNITY_BUILD})
set(CMAKE_UNITY_BUILD_BATCH_SIZE ${CCM_UNITY_BUILD_BATCH_SIZE})

# One precompiled header for the libraries: the headers most of their sources include, parsed once
# per build instead of once per translation unit. ccm_engine builds it; the other libraries reuse
# it (their extra compile definitions are not used by these headers). A source compiled with its
# own options sets SKIP_PRECOMPILE_HEADERS (engine/CMakeLists.txt).
set(CCM_LIBRARY_PCH_HEADERS <Eigen/Core> <Eigen/Geometry> <fmt/format.h> <algorithm> <array>
  <cmath> <filesystem> <map> <memory> <optional> <string> <string_view> <vector>)
# Under CCM_FUZZ a library instrumented for coverage cannot read a header precompiled without it
# (clang refuses it): those libraries share one precompiled with it, ccm_fuzz_pch's.
function(ccm_library_pch target)
  if(target STREQUAL "ccm_engine")
    target_precompile_headers(ccm_engine PRIVATE ${CCM_LIBRARY_PCH_HEADERS})
  elseif(CCM_FUZZ AND target IN_LIST CCM_FUZZ_COVERED_LIBRARIES)
    if(NOT TARGET ccm_fuzz_pch)
      file(WRITE ${PROJECT_BINARY_DIR}/ccm_fuzz_pch.cpp "")
      add_library(ccm_fuzz_pch OBJECT ${PROJECT_BINARY_DIR}/ccm_fuzz_pch.cpp)
      target_link_libraries(ccm_fuzz_pch PRIVATE Eigen3::Eigen fmt::fmt)
      target_compile_options(ccm_fuzz_pch PRIVATE -fsanitize=fuzzer-no-link)
      target_precompile_headers(ccm_fuzz_pch PRIVATE ${CCM_LIBRARY_PCH_HEADERS})
    endif()
    target_precompile_headers(${target} REUSE_FROM ccm_fuzz_pch)
  else()
    target_precompile_headers(${target} REUSE_FROM ccm_engine)
  endif()
endfunction()
