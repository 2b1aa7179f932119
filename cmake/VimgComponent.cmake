# The standard headers most of our sources include (the top of `grep -h '#include <'`). A target of
# many files parses them once, precompiled, instead of once per file: a third of a library file's
# compile time in Release and under the sanitizers (docs/benchmarks/ci.md "The CI run"). Emscripten
# builds the primitives without it, so their headers still have to say what they use.
set(VIMG_STD_PCH_HEADERS <string> <vector> <optional> <algorithm> <cmath> <cstdint> <cstddef> <string_view>
    <filesystem> <memory> <array> <utility> <span> <system_error> <variant> <map> <functional>)
# With a precompiled header, g++ 12 reports the standard library's own std::string code, inlined at
# -O2 and above, as ours: false -Wstringop-overflow, -Wstringop-overread and -Warray-bounds (GCC bugs
# 105329, 105651). Those stay off where g++ uses the header; clang's -Warray-bounds still runs on our
# code in the ASan build, and ASan checks every access at run time.
function(vimg_precompile_std target)
  if(NOT EMSCRIPTEN)
    target_precompile_headers(${target} PRIVATE ${VIMG_STD_PCH_HEADERS})
    target_compile_options(${target} PRIVATE $<$<CXX_COMPILER_ID:GNU>:-Wno-stringop-overflow -Wno-stringop-overread -Wno-array-bounds>)
  endif()
endfunction()

# vimg_component(NAME DIR [DEPS ...]): a library made of every .cpp below DIR (recursively).
# Files are picked up by glob so that adding a source never needs a CMake edit.
function(vimg_component name dir)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${dir}/*.cpp)
  list(FILTER sources EXCLUDE REGEX "/main\\.cpp$")
  if(sources)
    add_library(${name} STATIC ${sources})
    # Installed headers live under include/vibroimage/ (cmake/VimgExport.cmake).
    target_include_directories(${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                                              $<INSTALL_INTERFACE:include/vibroimage>)
    target_link_libraries(${name} PUBLIC ${ARG_DEPS})
    vimg_warnings(${name})
    vimg_precompile_std(${name})
  else()
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                                                 $<INSTALL_INTERFACE:include/vibroimage>)
    target_link_libraries(${name} INTERFACE ${ARG_DEPS})
  endif()
endfunction()

# vimg_test_dir(NAME DIR LIBS ... LABELS unit|threaded|gui|slow|limits [SERIAL]): one GoogleTest executable of
# every .cpp in DIR. SERIAL: its tests run alone (timing-sensitive runs of real-time loops).
function(vimg_test_dir name dir)
  cmake_parse_arguments(ARG "SERIAL" "" "LIBS;LABELS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${dir}/*.cpp)
  if(NOT sources)
    return()
  endif()
  add_executable(${name} ${sources})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest GTest::gtest_main GTest::gmock)
  target_compile_definitions(${name} PRIVATE
    VIMG_SOURCE_DIR="${PROJECT_SOURCE_DIR}" VIMG_BINARY_DIR="${PROJECT_BINARY_DIR}" VIMG_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/tests/data")
  vimg_warnings(${name})
  # The test files build at -O0 in every preset; the code under test keeps its preset's level (-O3
  # in Release, -O1 under the sanitizers). Optimising the expanded assertion macros was half of the
  # test files' build time, and at -O1 GCC 12 raises false -Warray-bounds and -Wstringop-overflow in
  # the tests' string concatenation. GoogleTest's header is parsed once per executable
  # (precompiled) with the common standard headers, not once per test file.
  target_precompile_headers(${name} PRIVATE <gtest/gtest.h> ${VIMG_STD_PCH_HEADERS})
  target_compile_options(${name} PRIVATE -O0)
  # One label per executable: gtest_discover_tests flattens a label list into separate properties.
  list(LENGTH ARG_LABELS label_count)
  if(NOT label_count EQUAL 1)
    message(FATAL_ERROR "vimg_test_dir(${name}): give exactly one label")
  endif()
  set(serial FALSE)
  if(ARG_SERIAL)
    set(serial TRUE)
  endif()
  # The TSan stage of .ci/run builds only these (target vimg_threaded_tests) and runs label threaded.
  if(ARG_LABELS STREQUAL "threaded")
    if(NOT TARGET vimg_threaded_tests)
      add_custom_target(vimg_threaded_tests)
    endif()
    add_dependencies(vimg_threaded_tests ${name})
  endif()
  gtest_discover_tests(${name} DISCOVERY_MODE PRE_TEST DISCOVERY_TIMEOUT 60
    PROPERTIES LABELS "${ARG_LABELS}" TIMEOUT 300 RUN_SERIAL ${serial})
endfunction()
