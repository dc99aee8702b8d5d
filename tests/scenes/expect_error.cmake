# ctest scenes.<bad>_is_a_clear_error. Requirement: a bad scene is an error that names the file and the entry,
# exits non-zero and leaves no report behind (neither a report folder nor a temporary).
# Variables: GRADCONTACT (the executable), SCENE (the bad scene), REPORTS (a scratch folder), EXPECTED (a
# regular expression the error output must match).
foreach(v GRADCONTACT SCENE REPORTS EXPECTED)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "expect_error.cmake: -D${v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${REPORTS}")
execute_process(COMMAND "${GRADCONTACT}" run "${SCENE}" --reports "${REPORTS}"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(status EQUAL 0)
  message(FATAL_ERROR "${SCENE}: exit code 0, expected an error\n${out}${err}")
endif()
if(NOT "${out}${err}" MATCHES "${EXPECTED}")
  message(FATAL_ERROR "${SCENE}: the message does not match '${EXPECTED}':\n${out}${err}")
endif()
if(EXISTS "${REPORTS}")
  file(GLOB left LIST_DIRECTORIES true "${REPORTS}/*" "${REPORTS}/.*")
  if(left)
    message(FATAL_ERROR "${SCENE}: the failed run left ${left}")
  endif()
endif()
message(STATUS "exit code ${status}, the expected message, no report left")
