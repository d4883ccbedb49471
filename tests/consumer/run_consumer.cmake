# ctest driver of the find_package(vantage) consumer test:
#   cmake -DBUILD_DIR=<vantage build> -DSOURCE_DIR=<tests/consumer> -DWORK_DIR=<scratch>
#         [-DBUILD_TYPE=<type>] [-DCONFIG=<config>] [-DCXX_COMPILER=<path>] [-DEXTRA_FLAGS=<flags>]
#         -P run_consumer.cmake
# installs the vantage build tree into WORK_DIR/prefix, configures and builds the consumer
# project against it through CMAKE_PREFIX_PATH alone, and runs the consumer program.
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_consumer.cmake: -D${var}=... is required")
  endif()
endforeach()

set(prefix "${WORK_DIR}/prefix")
set(consumer_build "${WORK_DIR}/build")
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

set(configure_args -S "${SOURCE_DIR}" -B "${consumer_build}" "-DCMAKE_PREFIX_PATH=${prefix}")
if(BUILD_TYPE)
  list(APPEND configure_args "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}")
endif()
if(CXX_COMPILER)
  list(APPEND configure_args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif()
if(EXTRA_FLAGS)
  list(APPEND configure_args "-DCMAKE_CXX_FLAGS=${EXTRA_FLAGS}"
    "-DCMAKE_EXE_LINKER_FLAGS=${EXTRA_FLAGS}")
endif()
run("configure" "${CMAKE_COMMAND}" ${configure_args})
run("build" "${CMAKE_COMMAND}" --build "${consumer_build}" ${config_args})

find_program(consumer_program vantage_consumer
  PATHS "${consumer_build}" "${consumer_build}/${CONFIG}" NO_DEFAULT_PATH)
if(NOT consumer_program)
  message(FATAL_ERROR "consumer test: vantage_consumer was not built in ${consumer_build}")
endif()
run("run" "${consumer_program}")
message(STATUS "${last_output}")
