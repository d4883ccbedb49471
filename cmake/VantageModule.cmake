# vantage_speed_up_build(<target> [TESTS])
#
# VANTAGE_UNITY_BUILD: compile <target> in unity batches (not with TESTS: the suites' file-local
# helpers share names). VANTAGE_PRECOMPILE_HEADERS: precompile <Eigen/Dense> (and, with TESTS,
# GoogleTest and GoogleMock) for <target>.
function(vantage_speed_up_build target)
  cmake_parse_arguments(ARG "TESTS" "" "" ${ARGN})
  if(VANTAGE_UNITY_BUILD AND NOT ARG_TESTS)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON)
  endif()
  if(VANTAGE_PRECOMPILE_HEADERS)
    target_precompile_headers(${target} PRIVATE <Eigen/Dense> <string> <vector>)
    if(ARG_TESTS)
      target_precompile_headers(${target} PRIVATE <gmock/gmock.h> <gtest/gtest.h>)
    endif()
  endif()
endfunction()

# vantage_sanitize_test_code(<target>)
#
# VANTAGE_SANITIZE (the Makefile's test-sanitize) instruments every library and the vantage
# command with AddressSanitizer and UndefinedBehaviorSanitizer. A suite's own code is compiled
# with AddressSanitizer only, for time: the suites are 110 of the build's 146 compilations, and
# UBSan made one about 1.4 to 1.7 times as long (placement_test.cc 11.8 s against 6.95 s,
# place_cli_test.cc 20.8 s against 15.3 s). The code under test keeps both. AddressSanitizer
# must stay: Eigen allocates differently under it (its own aligned blocks), so a suite without it
# freed a library's Eigen matrix with the wrong free (a bad-free in the cli suite, seen). (An
# inline function of a library header that a suite also instantiates may be linked from the
# suite's copy, without UBSan's checks.)
function(vantage_sanitize_test_code target)
  if(VANTAGE_SANITIZE)
    target_compile_options(${target} PRIVATE -fno-sanitize=undefined)
  endif()
endfunction()

# vantage_add_library(<name> [NLOPT] [EXPORT <set>] [PUBLIC_DEPS ...] [PRIVATE_DEPS ...])
#
# One static library per module: sources are src/*.cc, public headers are include/vantage/<name>/.
# Creates target vantage_<name> with alias vantage::<name> and adds it to the export set <set>
# (default vantageTargets, the core that find_package(vantage) gives; vantagePlotTargets is
# COMPONENTS plot). NLOPT: the module's sources see VANTAGE_WITH_NLOPT (1 or 0, the option) and
# link NLopt privately when it is 1.
function(vantage_add_library name)
  cmake_parse_arguments(ARG "NLOPT" "EXPORT" "PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  if(NOT ARG_EXPORT)
    set(ARG_EXPORT vantageTargets)
  endif()
  file(GLOB sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/src/*.cc")
  set(target vantage_${name})
  add_library(${target} ${sources})
  add_library(vantage::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name} POSITION_INDEPENDENT_CODE ON)
  target_include_directories(${target}
    PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:include>
    PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  target_compile_features(${target} PUBLIC cxx_std_17)
  target_compile_options(${target} PRIVATE ${VANTAGE_WARNINGS})
  target_link_libraries(${target} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  vantage_speed_up_build(${target})
  if(ARG_NLOPT)
    if(VANTAGE_WITH_NLOPT)
      target_compile_definitions(${target} PRIVATE VANTAGE_WITH_NLOPT=1)
      target_link_libraries(${target} PRIVATE NLopt::nlopt)
    else()
      target_compile_definitions(${target} PRIVATE VANTAGE_WITH_NLOPT=0)
    endif()
  endif()
  install(TARGETS ${target} EXPORT ${ARG_EXPORT}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  # include/vantage/<name>/internal/ holds headers shared by the modules only (e.g. the checks of
  # analysis/internal/checks.h): not part of the API, so not installed.
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
    PATTERN internal EXCLUDE)
endfunction()

# vantage_add_test_suite(<module> LIBS ... [DEFINITIONS ...] [EXCLUDE file ...] [EXTRA file ...]
#                        [LABEL <label>])
#
# One GoogleTest executable per module from tests/<module>/*_test.cc (without EXCLUDE, plus
# EXTRA; both relative to tests/), each test registered with ctest through gtest_discover_tests.
# Every suite sees VANTAGE_WITH_NLOPT and VANTAGE_WITH_PLOT (1 or 0, the options), so that a test
# can hold the library's own answer (built_with_nlopt()) against the build's. Its tests carry the
# CTest label <label> (default: <module>).
function(vantage_add_test_suite module)
  cmake_parse_arguments(ARG "" "LABEL" "LIBS;DEFINITIONS;EXCLUDE;EXTRA" ${ARGN})
  if(NOT ARG_LABEL)
    set(ARG_LABEL ${module})
  endif()
  file(GLOB sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/${module}/*_test.cc")
  foreach(file ${ARG_EXCLUDE})
    list(REMOVE_ITEM sources "${CMAKE_CURRENT_SOURCE_DIR}/${file}")
  endforeach()
  foreach(file ${ARG_EXTRA})
    list(APPEND sources "${CMAKE_CURRENT_SOURCE_DIR}/${file}")
  endforeach()
  if(NOT sources)
    return()
  endif()
  set(target vantage_${module}_tests)
  add_executable(${target} ${sources})
  target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_options(${target} PRIVATE ${VANTAGE_WARNINGS})
  if(VANTAGE_WITH_NLOPT)
    set(with_nlopt 1)
  else()
    set(with_nlopt 0)
  endif()
  if(TARGET vantage::plot)
    set(with_plot 1)
  else()
    set(with_plot 0)
  endif()
  target_compile_definitions(${target} PRIVATE VANTAGE_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    VANTAGE_WITH_NLOPT=${with_nlopt} VANTAGE_WITH_PLOT=${with_plot} ${ARG_DEFINITIONS})
  target_link_libraries(${target} PRIVATE ${ARG_LIBS} GTest::gmock GTest::gtest_main)
  vantage_sanitize_test_code(${target})
  vantage_speed_up_build(${target} TESTS)
  gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 PROPERTIES LABELS ${ARG_LABEL})
endfunction()
