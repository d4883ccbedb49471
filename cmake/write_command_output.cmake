# cmake "-DCOMMAND_LINE=prog;arg;..." -DOUTPUT=FILE -P write_command_output.cmake: runs the
# command and writes its standard output to FILE; fails when the command fails.
execute_process(COMMAND ${COMMAND_LINE} OUTPUT_FILE "${OUTPUT}.tmp" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${COMMAND_LINE}: exit status ${status}")
endif()
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
