# Post-build check of a Catch2 test executable: every test case carries one of the tags that ctest
# registers (TAGS, e.g. "fem;verification;slow"), so none is compiled and silently never run.
# Variables: EXECUTABLE, TAGS.
foreach(v EXECUTABLE TAGS)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "check_tags.cmake: -D${v}=... is required")
  endif()
endforeach()
set(spec "")
foreach(tag ${TAGS})
  string(APPEND spec "~[${tag}]")
endforeach()
execute_process(COMMAND "${EXECUTABLE}" --list-test-names-only "${spec}"
                RESULT_VARIABLE status OUTPUT_VARIABLE untagged ERROR_VARIABLE err)
string(STRIP "${untagged}" untagged)
if(NOT untagged STREQUAL "")
  message(FATAL_ERROR "${EXECUTABLE}: test cases without any of the tags [${TAGS}] would never run under "
                      "ctest; tag them:\n${untagged}")
endif()
