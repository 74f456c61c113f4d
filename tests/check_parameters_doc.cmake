# Compares `EXECUTABLE --print-parameters md` (written to OUTPUT) with the file EXPECTED.
get_filename_component(_dir ${OUTPUT} DIRECTORY)
file(MAKE_DIRECTORY ${_dir})
execute_process(COMMAND ${EXECUTABLE} --print-parameters md
  OUTPUT_FILE ${OUTPUT} RESULT_VARIABLE _status)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "porofrac --print-parameters md failed (${_status})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUTPUT} ${EXPECTED}
  RESULT_VARIABLE _different)
if(_different)
  message(FATAL_ERROR "${EXPECTED} is not what porofrac prints (${OUTPUT}); regenerate it: "
    "porofrac --print-parameters md > doc/parameters.md")
endif()
