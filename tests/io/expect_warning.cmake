# Runs COMMAND (a ;-list) and passes if it ends within TIMEOUT seconds with exit status 0 and a
# stderr with a line matching REGEX (a warning: the run goes on).
#   cmake -DCOMMAND=... -DREGEX=... [-DTIMEOUT=s] -P expect_warning.cmake
if(NOT TIMEOUT)
  set(TIMEOUT 30)
endif()
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE out TIMEOUT ${TIMEOUT})
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "exit status ${rc}, expected 0\nstderr: ${err}")
endif()
if(NOT err MATCHES "${REGEX}")
  message(FATAL_ERROR "no warning matching\n  ${REGEX}\nin\n${err}")
endif()
message(STATUS "warned: ${REGEX}")
