# Smoke test of `gradcontact bench --part fe --quick` (ctest: bench.fe_quick_smoke).
# Requirement: the FE work-precision benchmark shall write its table, markdown and plots, and every
# run in it shall give a finite relative error below MAX_ERROR (the quick set is degree 1-2 on the two
# coarsest meshes, k = 0, and the JKR pull-off and tangential punch on the coarsest mesh, whose errors lie
# below MAX_ERROR (reports/benchmarks/fe_work_precision.md of `./vv bench` lists them); a broken solver,
# reference or parser gives inf, NaN or O(1) and fails here).
# Variables: GRADCONTACT (the executable), REPORTS (a scratch folder), MAX_ERROR.
foreach(v GRADCONTACT REPORTS MAX_ERROR)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "smoke.cmake: -D${v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${REPORTS}")
execute_process(COMMAND "${GRADCONTACT}" bench --part fe --quick --reports "${REPORTS}"
                RESULT_VARIABLE status ERROR_VARIABLE log OUTPUT_VARIABLE out)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "gradcontact bench failed (${status}):\n${log}")
endif()
set(folder "${REPORTS}/benchmarks")
foreach(f fe_work_precision.csv fe_work_precision.md
          fe_flat_punch_k0_error_vs_time.gp fe_flat_punch_k0_error_vs_time.dat
          fe_paraboloid_k0_error_vs_dofs.gp fe_paraboloid_k0_error_vs_dofs.dat)
  if(NOT EXISTS "${folder}/${f}")
    message(FATAL_ERROR "missing ${folder}/${f}")
  endif()
endforeach()
file(STRINGS "${folder}/fe_work_precision.csv" lines)
list(LENGTH lines n)
# header + 2 normal scenes x 2 degrees x 2 levels + 2 (JKR pull-off, tangential punch) x 2 degrees x 1 level
if(n LESS 13)
  message(FATAL_ERROR "fe_work_precision.csv has ${n} lines, expected 13:\n${lines}")
endif()
list(REMOVE_AT lines 0)
foreach(line IN LISTS lines)
  string(REPLACE "," ";" fields "${line}")
  list(GET fields 11 error)
  list(GET fields 8 dofs)
  # if(LESS) parses a real number; inf and nan are never less than the bound
  if(NOT error MATCHES "^[0-9.eE+-]+$" OR NOT error LESS MAX_ERROR OR NOT dofs GREATER 0)
    message(FATAL_ERROR "bad run (error ${error} >= ${MAX_ERROR} or not finite, or no DoFs): ${line}")
  endif()
  message(STATUS "ok: ${line}")
endforeach()
