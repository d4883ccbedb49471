# ctest driver of the find_package(vantage) consumer tests:
#   cmake -DBUILD_DIR=<vantage build> -DSOURCE_DIR=<tests/consumer> -DWORK_DIR=<scratch>
#         -DWITH_PLOT=<ON|OFF> [-DBUILD_TYPE=<type>] [-DCONFIG=<config>] [-DCXX_COMPILER=<path>]
#         [-DEXTRA_FLAGS=<flags>] -P run_consumer.cmake
# installs the vantage build tree into WORK_DIR/prefix, then, through CMAKE_PREFIX_PATH alone:
#  - core/: find_package(vantage) with pkg-config disabled (so it cannot reach PLplot, cairo or
#    libpng), built and run;
#  - plot/: find_package(vantage COMPONENTS plot), built and run when vantage has plot
#    (WITH_PLOT); otherwise its configure must fail and say that vantage was built without it.
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR WITH_PLOT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_consumer.cmake: -D${var}=... is required")
  endif()
endforeach()

set(prefix "${WORK_DIR}/prefix")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "consumer test: ${step} failed (${status})\n${out}\n${err}")
  endif()
  message(STATUS "consumer test: ${step}: ok")
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

set(config_args)
if(CONFIG)
  set(config_args --config "${CONFIG}")
endif()
run("install" "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}" ${config_args})

# The configure arguments of consumer project `name` (a folder of SOURCE_DIR), built in
# WORK_DIR/<name>.
function(configure_args name out)
  set(args -S "${SOURCE_DIR}/${name}" -B "${WORK_DIR}/${name}" "-DCMAKE_PREFIX_PATH=${prefix}"
    ${ARGN})
  if(BUILD_TYPE)
    list(APPEND args "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}")
  endif()
  if(CXX_COMPILER)
    list(APPEND args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
  endif()
  if(EXTRA_FLAGS)
    list(APPEND args "-DCMAKE_CXX_FLAGS=${EXTRA_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${EXTRA_FLAGS}")
  endif()
  set(${out} ${args} PARENT_SCOPE)
endfunction()

function(find_program_in name program out)
  find_program(found_${program} ${program}
    PATHS "${WORK_DIR}/${name}" "${WORK_DIR}/${name}/${CONFIG}" NO_DEFAULT_PATH)
  if(NOT found_${program})
    message(FATAL_ERROR "consumer test: ${program} was not built in ${WORK_DIR}/${name}")
  endif()
  set(${out} "${found_${program}}" PARENT_SCOPE)
endfunction()

configure_args(core args -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=TRUE)
run("core: configure (no pkg-config)" "${CMAKE_COMMAND}" ${args})
run("core: build" "${CMAKE_COMMAND}" --build "${WORK_DIR}/core" ${config_args})
find_program_in(core vantage_consumer program)
run("core: run" "${program}")
message(STATUS "${last_output}")

configure_args(plot args)
if(WITH_PLOT)
  run("plot: configure" "${CMAKE_COMMAND}" ${args})
  run("plot: build" "${CMAKE_COMMAND}" --build "${WORK_DIR}/plot" ${config_args})
  find_program_in(plot vantage_consumer_plot program)
  file(MAKE_DIRECTORY "${WORK_DIR}/figures")
  run("plot: run" "${program}" "${WORK_DIR}/figures")
  message(STATUS "${last_output}")
else()
  execute_process(COMMAND "${CMAKE_COMMAND}" ${args}
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(status EQUAL 0 OR NOT "${out}${err}" MATCHES "component plot: vantage was built without it")
    message(FATAL_ERROR "consumer test: find_package(vantage COMPONENTS plot) of a vantage "
      "without plot did not fail as it should (${status})\n${out}\n${err}")
  endif()
  message(STATUS "consumer test: plot: not found, as vantage has no plot: ok")
endif()
