# Runs the fuzzer for SECONDS from a fresh corpus seeded with the JSON files under
# SEEDS; fails on any crash, leak, sanitizer report or timeout the fuzzer finds.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
foreach(dir ${SEEDS})
  file(GLOB_RECURSE seeds ${dir}/*.json)
  foreach(seed ${seeds})
    file(RELATIVE_PATH name ${dir} ${seed})
    string(REPLACE "/" "_" name ${name})
    configure_file(${seed} ${WORK}/${name} COPYONLY)
  endforeach()
endforeach()
execute_process(
  COMMAND ${FUZZER} ${WORK} -dict=${DICT} -max_total_time=${SECONDS} -timeout=10 -rss_limit_mb=2048
          -max_len=8192 -print_final_stats=1 -artifact_prefix=${WORK}/../
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "fuzz_loader found a failure (exit ${result}); the input is saved beside ${WORK}")
endif()
