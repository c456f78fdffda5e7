# Runs a verification driver with a deliberately tightened tolerance file and passes only
# if the driver exits with status 1 and prints the FAIL line naming the quantity, the
# measured value and the limit. Proves end to end that the CTest gate can fail.
#
#   cmake -DDRIVER=<exe> -DTOLERANCES=<file> -DOUTPUT_DIR=<dir> -DEXPECTED=<regex>
#         -P expect_tolerance_failure.cmake
foreach(var DRIVER TOLERANCES OUTPUT_DIR EXPECTED)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "expect_tolerance_failure: -D${var}=... is required")
  endif()
endforeach()
execute_process(
  COMMAND ${DRIVER} --mode quick --output-dir ${OUTPUT_DIR} --tolerances ${TOLERANCES}
  RESULT_VARIABLE status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
if(NOT status EQUAL 1)
  message(FATAL_ERROR "expected exit status 1 from a violated tolerance, got '${status}'\n"
                      "stdout:\n${out}\nstderr:\n${err}")
endif()
if(NOT out MATCHES "${EXPECTED}")
  message(FATAL_ERROR "the FAIL message does not match '${EXPECTED}'\nstdout:\n${out}")
endif()
string(REGEX MATCH "FAIL [^\n]*" line "${out}")
message(STATUS "driver failed as expected: ${line}")
