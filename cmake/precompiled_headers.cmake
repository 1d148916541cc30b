# Precompiled headers (GC_PCH, on by default): Eigen, GoogleTest, protobuf, fmt, spdlog, Cyclone
# and the standard library are most of what a translation unit of this tree parses (every one
# reaches Eigen through core/). Measured on a sample (2026-11-29, tests/run_all.sh's flags):
# a third to a half less compile time a unit, with GCC and with clang. Off for a build that wants
# each source to compile on its own includes alone (the precompiled headers are included first).
option(GC_PCH "Precompile the heavy third-party and standard headers" ON)

set(gc_pch_std <algorithm> <array> <chrono> <cmath> <cstddef> <cstdint> <functional> <map>
    <memory> <optional> <span> <string> <string_view> <utility> <vector>)

# gc_precompile_headers(<target> <header>...): the target's own precompiled header, of the
# standard headers above and the given ones (a header per target: a shared library's units
# define <target>_EXPORTS and may be -fPIC, which a precompiled header must match).
function(gc_precompile_headers target)
  if(GC_PCH)
    target_precompile_headers(${target} PRIVATE ${ARGN} ${gc_pch_std})
  endif()
endfunction()

# gc_test_precompiled_headers(<directory>): every GoogleTest program defined under <directory>
# that links one of this tree's libraries reuses one precompiled header, of GoogleTest, Eigen
# and the standard headers, built once by gc_test_pch (whose only macro, GTEST_HAS_PTHREAD, they
# all define; GCC ignores a precompiled header whose macros differ, clang refuses it).
function(gc_test_precompiled_headers directory)
  if(NOT GC_PCH)
    return()
  endif()
  if(NOT TARGET gc_test_pch)
    find_package(GTest REQUIRED)   # its targets are known where it was found: here too
    file(WRITE ${PROJECT_BINARY_DIR}/gc_test_pch.cc "// gc_test_pch: the tests' precompiled header\n")
    add_library(gc_test_pch STATIC ${PROJECT_BINARY_DIR}/gc_test_pch.cc)
    target_link_libraries(gc_test_pch PRIVATE GTest::gtest Eigen3::Eigen)
    target_precompile_headers(gc_test_pch PRIVATE <gtest/gtest.h> <Eigen/Dense> ${gc_pch_std})
  endif()
  get_property(targets DIRECTORY ${directory} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    get_target_property(libraries ${target} LINK_LIBRARIES)
    if(NOT type STREQUAL "EXECUTABLE" OR NOT libraries)
      continue()
    endif()
    set(gtest OFF)
    set(ours OFF)
    foreach(library IN LISTS libraries)
      if(library MATCHES "^GTest::")
        set(gtest ON)
      elseif(library MATCHES "^gc_")
        set(ours ON)
      endif()
    endforeach()
    if(gtest AND ours)
      target_precompile_headers(${target} REUSE_FROM gc_test_pch)
    endif()
  endforeach()
  get_property(subdirectories DIRECTORY ${directory} PROPERTY SUBDIRECTORIES)
  foreach(subdirectory IN LISTS subdirectories)
    gc_test_precompiled_headers(${subdirectory})
  endforeach()
endfunction()
