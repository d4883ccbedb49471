# vantage_add_library(<name> [PUBLIC_DEPS ...] [PRIVATE_DEPS ...])
#
# One static library per module: sources are src/*.cc, public headers are include/vantage/<name>/.
# Creates target vantage_<name> with alias vantage::<name> and adds it to the vantageTargets
# export set so that find_package(vantage) provides vantage::<name>.
function(vantage_add_library name)
  cmake_parse_arguments(ARG "" "" "PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
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
  install(TARGETS ${target} EXPORT vantageTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  # include/vantage/<name>/internal/ holds headers shared by the modules only (e.g. the checks of
  # analysis/internal/checks.h): not part of the API, so not installed.
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
    PATTERN internal EXCLUDE)
endfunction()

# vantage_add_test_suite(<module> LIBS ...)
#
# One GoogleTest executable per module from tests/<module>/*_test.cc, each test registered with
# ctest through gtest_discover_tests.
function(vantage_add_test_suite module)
  cmake_parse_arguments(ARG "" "" "LIBS;DEFINITIONS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/${module}/*_test.cc")
  if(NOT sources)
    return()
  endif()
  set(target vantage_${module}_tests)
  add_executable(${target} ${sources})
  target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_options(${target} PRIVATE ${VANTAGE_WARNINGS})
  target_compile_definitions(${target} PRIVATE
    VANTAGE_SOURCE_DIR="${PROJECT_SOURCE_DIR}" ${ARG_DEFINITIONS})
  target_link_libraries(${target} PRIVATE ${ARG_LIBS} GTest::gmock GTest::gtest_main)
  gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 PROPERTIES LABELS ${module})
endfunction()
