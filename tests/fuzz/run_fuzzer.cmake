# Runs a libFuzzer target for a bounded, reproducible time (ctest fuzz.*).
#
#   cmake -DFUZZER=<exe> -DSEEDS=<dir> [-DREGRESSIONS=<dir>] [-DDICT=<file>]
#         -DWORK_DIR=<dir> -DRUNS=<n> -DMAX_TIME=<s> -P run_fuzzer.cmake
#
# 1. Every file in REGRESSIONS (inputs that once crashed) is run once; the
#    test stops there if one fails, and names it.
# 2. The fuzzer runs with a fixed seed for RUNS executions (at most MAX_TIME
#    seconds) from the seeds, named to it in sorted order (-seed_inputs): what
#    it adds to the corpus (WORK_DIR/corpus), and any crash-*/leak-*/timeout-*
#    file, stays in WORK_DIR.
#    Runs stay alike from one machine to the next: without address
#    randomisation (below), and with the seeds in one order. libFuzzer orders
#    a corpus directory's files by size and leaves files of equal size in the
#    order the file system lists them, which differs between file systems
#    (ext4 by a hash of the name, tmpfs newest first), and a different order
#    is a different run.
foreach(var FUZZER SEEDS WORK_DIR RUNS MAX_TIME)
    if(NOT DEFINED ${var})
        message(FATAL_ERROR "run_fuzzer.cmake: ${var} is not set")
    endif()
endforeach()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/corpus)
file(GLOB seeds LIST_DIRECTORIES false ${SEEDS}/*)
if(NOT seeds)
    message(FATAL_ERROR "no seed inputs in ${SEEDS}")
endif()
list(SORT seeds)
list(JOIN seeds "," seed_inputs)

# An input is a hang at 30 s of wall time. Instrumented code runs 20 to 40
# times slower than a release build, and beside other tests on two cores an
# input taking 0.18 s in release (a fuzzed pile of 150 welded cubes, 6 s here
# before the check paired copies without the tree; regressions/) passed 10 s.
set(common_options -rss_limit_mb=2048 -timeout=30 -artifact_prefix=${WORK_DIR}/)
# The dictionary (a text format's keywords) guides the mutations only.
set(dictionary_option)
if(DEFINED DICT)
    set(dictionary_option -dict=${DICT})
endif()

# The library compares addresses (its array bounds checks) and libFuzzer feeds
# compared values back into its mutations, so with address space layout
# randomisation two runs of one seed soon part ways. setarch -R (util-linux)
# turns it off for the fuzzer, where the system allows it, so that runs stay alike.
set(launcher)
find_program(SETARCH setarch)
if(SETARCH)
    execute_process(COMMAND ${SETARCH} -R true RESULT_VARIABLE result OUTPUT_QUIET ERROR_QUIET)
    if(result EQUAL 0)
        set(launcher ${SETARCH} -R)
    endif()
endif()
if(NOT launcher)
    message(STATUS "setarch -R is not available: runs of one seed will differ")
endif()

if(DEFINED REGRESSIONS AND IS_DIRECTORY ${REGRESSIONS})
    file(GLOB regressions LIST_DIRECTORIES false ${REGRESSIONS}/*)
    list(FILTER regressions EXCLUDE REGEX "/README[^/]*$")
    set(failed)
    # Each replay's output is kept for a failure only: a passing replay says
    # nothing worth reading, and a failing run's own report should not drown.
    foreach(input IN LISTS regressions)
        execute_process(COMMAND ${launcher} ${FUZZER} ${common_options} ${input}
            WORKING_DIRECTORY ${WORK_DIR}
            RESULT_VARIABLE result
            OUTPUT_VARIABLE output ERROR_VARIABLE output)
        if(NOT result EQUAL 0)
            message("${output}")
            list(APPEND failed ${input})
        endif()
    endforeach()
    list(LENGTH regressions count)
    if(failed)
        list(JOIN failed "\n  " failed_list)
        message(FATAL_ERROR "regression input(s) that fail (see above):\n  ${failed_list}\n"
                            "look at one: POLYMASS_FUZZ_VERBOSE=1 ${FUZZER} <input>")
    endif()
    message(STATUS "${count} regression input(s) from ${REGRESSIONS}: all pass")
endif()

message(STATUS "fuzzing: ${RUNS} runs, seed 1, at most ${MAX_TIME} s, corpus ${WORK_DIR}/corpus")
execute_process(
    COMMAND ${launcher} ${FUZZER} ${common_options}
        -seed=1 -runs=${RUNS} -max_total_time=${MAX_TIME} -max_len=8192
        ${dictionary_option} -print_final_stats=1 -seed_inputs=${seed_inputs}
        ${WORK_DIR}/corpus
    WORKING_DIRECTORY ${WORK_DIR}
    RESULT_VARIABLE result
    OUTPUT_FILE ${WORK_DIR}/fuzzer.log ERROR_FILE ${WORK_DIR}/fuzzer.log)
# Its progress lines run to thousands: the closing statistics when it passes,
# the end of the log (the sanitizer's report) when it fails.
if(result EQUAL 0)
    file(STRINGS ${WORK_DIR}/fuzzer.log closing REGEX "^(stat::|Done [0-9]+ runs)")
    list(JOIN closing "\n" closing)
    message("${closing}\n(the whole log: ${WORK_DIR}/fuzzer.log)")
else()
    file(READ ${WORK_DIR}/fuzzer.log log)
    string(LENGTH "${log}" log_length)
    set(tail_length 6000)
    if(log_length GREATER tail_length)
        math(EXPR from "${log_length} - ${tail_length}")
        string(SUBSTRING "${log}" ${from} -1 log)
    endif()
    message("...\n${log}")
endif()
if(NOT result EQUAL 0)
    file(GLOB artifacts ${WORK_DIR}/crash-* ${WORK_DIR}/leak-* ${WORK_DIR}/timeout-*
         ${WORK_DIR}/oom-* ${WORK_DIR}/slow-unit-*)
    # The failing input itself, in hexadecimal: where only this log comes back
    # (a CI machine), it is the reproducer.
    foreach(artifact IN LISTS artifacts)
        file(READ ${artifact} bytes HEX)
        message("${artifact} (hexadecimal; xxd -r -p turns it back into the file):\n${bytes}")
    endforeach()
    message(FATAL_ERROR "the fuzzer failed (exit ${result}); input(s): ${artifacts}\n"
                        "reproduce: ${FUZZER} <input>  (POLYMASS_FUZZ_VERBOSE=1 decodes it)")
endif()
