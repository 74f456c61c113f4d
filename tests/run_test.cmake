# Runs one PoroFrac test (see tests/CMakeLists.txt) and compares its output with numdiff.
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
string(REPLACE "|" ";" EXTRA_ARGS "${EXTRA_ARGS}")
string(REPLACE "|" ";" NUMDIFF_ARGS "${NUMDIFF_ARGS}")
if(INPUT)
  # Tests compare the results report only: no progress lines, no timer tables.
  set(_command ${EXECUTABLE} ${INPUT} --output-dir ${WORKDIR}/out
    --set Output/Verbosity=quiet --set "Output/Timer output=none" ${EXTRA_ARGS})
else()
  set(_command ${EXECUTABLE} ${EXTRA_ARGS})
endif()
if(MPI_PROCESSES GREATER 0)
  # --oversubscribe: Open MPI refuses more processes than it counts free cores otherwise;
  # -q: no notices of mpirun's own (about the process that exited first, with a job id), so that
  # the output of a failing run is porofrac's message alone.
  set(_command ${MPIEXEC} ${MPIEXEC_NUMPROC_FLAG} ${MPI_PROCESSES} --oversubscribe -q ${_command})
endif()
execute_process(COMMAND ${_command}
  WORKING_DIRECTORY ${WORKDIR}
  OUTPUT_VARIABLE _out ERROR_VARIABLE _err RESULT_VARIABLE _status)
file(WRITE ${WORKDIR}/output "${_out}${_err}")
if(EXPECT_FAILURE)
  # Bad input exits with 1, a command-line error with 2, a solver failure with 3; anything else
  # (4: internal error, a signal) is a defect even where failure is expected.
  if(NOT _status MATCHES "^[123]$")
    message(FATAL_ERROR "The run was expected to fail with status 1, 2 or 3 but gave '${_status}':\n${_out}${_err}")
  endif()
elseif(NOT _status EQUAL 0)
  message(FATAL_ERROR "The run exited with status ${_status}:\n${_out}${_err}")
endif()
if(NOT EXISTS ${EXPECTED})
  message(FATAL_ERROR "No expected output ${EXPECTED}; this run's output is ${WORKDIR}/output")
endif()
execute_process(COMMAND ${NUMDIFF} -q ${NUMDIFF_ARGS} -s " \t\n=,:<>[](){}^" ${EXPECTED} ${WORKDIR}/output
  OUTPUT_VARIABLE _diff ERROR_VARIABLE _diff_err RESULT_VARIABLE _differs)
if(NOT _differs EQUAL 0)
  execute_process(COMMAND ${NUMDIFF} ${NUMDIFF_ARGS} -s " \t\n=,:<>[](){}^" ${EXPECTED} ${WORKDIR}/output
    OUTPUT_VARIABLE _diff)
  message(FATAL_ERROR "Output differs from ${EXPECTED}:\n${_diff}")
endif()
message(STATUS "Output matches ${EXPECTED}")
