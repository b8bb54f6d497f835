# Warnings as an interface target every ccm target links to.
add_library(ccm_warnings INTERFACE)
add_library(ccm::warnings ALIAS ccm_warnings)
target_compile_options(ccm_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
  -Wnon-virtual-dtor -Wold-style-cast -Woverloaded-virtual -Wnull-dereference
  -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough)
