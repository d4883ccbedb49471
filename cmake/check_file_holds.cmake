# cmake -DPAGE=FILE "-DEXPECTED=a;b" -P check_file_holds.cmake: fails unless FILE exists and
# holds every fragment of EXPECTED (a CTest of generated files, such as the man pages).
if(NOT EXISTS "${PAGE}")
  message(FATAL_ERROR "${PAGE}: missing")
endif()
file(READ "${PAGE}" text)
foreach(fragment IN LISTS EXPECTED)
  string(FIND "${text}" "${fragment}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${PAGE}: does not hold \"${fragment}\"")
  endif()
endforeach()
