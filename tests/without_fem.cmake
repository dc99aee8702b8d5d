# ctest house.builds_and_tests_without_fem: configures SOURCE with -DGRADCONTACT_WITH_FEM=OFF in BINARY, builds it
# and runs its ctest (the analytic tests and `gradcontact eval`); any failure is the test's.
foreach(v SOURCE BINARY)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "without_fem.cmake: -D${v}=... is required")
  endif()
endforeach()
foreach(step "configure;${CMAKE_COMMAND};-S;${SOURCE};-B;${BINARY};-DGRADCONTACT_WITH_FEM=OFF;-DCMAKE_BUILD_TYPE=Release"
             "build;${CMAKE_COMMAND};--build;${BINARY};-j2"
             "test;${CMAKE_CTEST_COMMAND};--test-dir;${BINARY};-j2;--output-on-failure")
  list(POP_FRONT step name)
  execute_process(COMMAND ${step} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "without the FE module, ${name} failed (${status}):\n${out}\n${err}")
  endif()
  message(STATUS "without the FE module, ${name}: ok")
endforeach()
