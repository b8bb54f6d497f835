# Warnings as an interface target every ccm target links to.
add_library(ccm_warnings INTERFACE)
add_library(ccm::warnings ALIAS ccm_warnings)
target_compile_options(ccm_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
  -Wnon-virtual-dtor -Wold-style-cast -Woverloaded-virtual -Wnull-dereference
  -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough)

# GCC 12 reports -Wmaybe-uninitialized inside Eigen 3.4's AVX-512 reduction (predux of an
# 8-double packet: _mm512_extractf64x4_pd on _mm256_undefined_pd, avx512fintrin.h) wherever a
# dynamic matrix-vector product is built with -march=native on a CPU with AVX-512: a false
# positive in a system header, inlined into the targets that use Eigen's least squares (the
# study's surface fits, the rig's signal fits). Silenced for those targets only.
function(ccm_silence_eigen_avx512_false_positive target)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-maybe-uninitialized)
  endif()
endfunction()
