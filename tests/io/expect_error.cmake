# Runs COMMAND (a ;-list) and passes if it ends within TIMEOUT seconds with an exit status in
# [1, 127] (exactly STATUS if given) and a stderr whose last line matches REGEX (the one-line error
# of a refused input).
#   cmake -DCOMMAND=... -DREGEX=... [-DTIMEOUT=s] [-DSTATUS=n] -P expect_error.cmake
if(NOT TIMEOUT)
  set(TIMEOUT 10)
endif()
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE out TIMEOUT ${TIMEOUT})
string(STRIP "${err}" err)
string(REGEX REPLACE ".*\n" "" last "${err}")
if(NOT rc MATCHES "^[0-9]+$")
  message(FATAL_ERROR "did not end normally within ${TIMEOUT} s: ${rc}\nstderr: ${err}")
endif()
if(rc EQUAL 0 OR rc GREATER 127)
  message(FATAL_ERROR "exit status ${rc}, expected 1..127\nstdout: ${out}\nstderr: ${err}")
endif()
if(DEFINED STATUS AND NOT rc EQUAL STATUS)
  message(FATAL_ERROR "exit status ${rc}, expected ${STATUS}\nstderr: ${err}")
endif()
if(NOT last MATCHES "${REGEX}")
  message(FATAL_ERROR "the error line\n  ${last}\ndoes not match\n  ${REGEX}")
endif()
message(STATUS "refused with status ${rc}: ${last}")
