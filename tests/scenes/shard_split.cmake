# ctest scenes.shard_splits_a_sweep. Requirement ("how a sweep runs on a cluster"):
# `--shard i/N` gives every value of a sweep to exactly one of N independent jobs, and each job writes
# its own summary (summary.shard-i-of-N.md), so N jobs may share one reports folder.
# Variables: GRADCONTACT (the executable), SCENE (a fast .prm scene), REPORTS (a scratch folder).
foreach(v GRADCONTACT SCENE REPORTS)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "shard_split.cmake: -D${v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${REPORTS}")
set(values -0.5 0 0.5)
foreach(shard 0 1)
  execute_process(COMMAND "${GRADCONTACT}" sweep "${SCENE}" --over "Material/k=-0.5,0,0.5"
                          --shard ${shard}/2 --quiet --reports "${REPORTS}"
                  RESULT_VARIABLE status ERROR_VARIABLE log)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "shard ${shard}/2 failed (${status}):\n${log}")
  endif()
  if(NOT EXISTS "${REPORTS}/summary.shard-${shard}-of-2.md")
    message(FATAL_ERROR "shard ${shard}/2 wrote no summary.shard-${shard}-of-2.md")
  endif()
endforeach()
# Positions 0 and 2 (k = -0.5, 0.5) belong to shard 0, position 1 (k = 0) to shard 1: every value once.
file(READ "${REPORTS}/summary.shard-0-of-2.md" s0)
file(READ "${REPORTS}/summary.shard-1-of-2.md" s1)
get_filename_component(stem "${SCENE}" NAME_WE)
foreach(pair "s0;-0.5;1" "s0;0;0" "s0;0.5;1" "s1;-0.5;0" "s1;0;1" "s1;0.5;0")
  list(GET pair 0 var)
  list(GET pair 1 k)
  list(GET pair 2 expected)
  string(FIND "${${var}}" "| ${stem}-k=${k} |" at)
  if((expected AND at EQUAL -1) OR (NOT expected AND NOT at EQUAL -1))
    message(FATAL_ERROR "k = ${k}: expected ${expected} row(s) in ${var}:\n${${var}}")
  endif()
endforeach()
execute_process(COMMAND "${GRADCONTACT}" sweep "${SCENE}" --over "Material/k=0" --shard 2/2 --quiet
                        --reports "${REPORTS}" RESULT_VARIABLE status ERROR_VARIABLE log)
if(status EQUAL 0 OR NOT log MATCHES "--shard '2/2' is not i/N")
  message(FATAL_ERROR "--shard 2/2 was not refused with a clear message (${status}): ${log}")
endif()
