# tests/distributed/CMakeLists.txt: mpi_verify_cases. `veridem verify` of the cases CASES (a ;-list) in one
# process and under mpirun on each count in RANKS, compared by compare_verify.py (-DLIMIT: largest
# relative difference of a measured value; 0: the same bits; none: verdicts only). With
# -DALLOW_FAILING=ON a case may fail (exit status 1), as long as it fails on every rank count.
# -DVERIDEM, -DMPIEXEC, -DCOMPARE, -DWORK.
file(REMOVE_RECURSE ${WORK})
set(selection)
foreach(name ${CASES})
  list(APPEND selection --case ${name})
endforeach()
set(results)
foreach(ranks 1 ${RANKS})
  if(ranks EQUAL 1)
    set(command ${VERIDEM})
  else()
    set(command ${MPIEXEC} -np ${ranks} ${VERIDEM})
  endif()
  execute_process(COMMAND ${command} verify ${selection} --quiet --json ${WORK}/np${ranks}.json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 AND NOT (ALLOW_FAILING AND rc EQUAL 1))
    message(FATAL_ERROR "${ranks} rank(s): exit ${rc}\n${out}\n${err}")
  endif()
  list(APPEND results ${WORK}/np${ranks}.json)
endforeach()
execute_process(COMMAND python3 ${COMPARE} ${results} --max-relative ${LIMIT} RESULT_VARIABLE rc
                OUTPUT_VARIABLE out)
message(STATUS "${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the results differ between rank counts")
endif()
