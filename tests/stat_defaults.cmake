# rtlab-stat's defaults are the statistical tests' tolerance (RTLAB_STAT_TOLERANCE in
# tools/settings.cmake), so that a test run by hand gives the suite's verdict: the same
# verdict (its JSON: alpha, level, var_renders, the count of failures) with and without
# TOLERANCE on the command line. The renders are the reference's own mean and another
# scene's, so that thousands of values fail, as many as the floor lets through.
foreach(run bare given)
    set(args "")
    if(run STREQUAL "given")
        set(args ${TOLERANCE})
    endif()
    execute_process(COMMAND ${STAT} test ${MEAN} ${VAR} ${MEAN} ${OTHER} ${args} --json ${WORK}/${run}.json
        RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
    if(NOT code EQUAL 1)  # the other scene must fail
        message(FATAL_ERROR "rtlab-stat (${run}) exited ${code}, not 1: ${err}")
    endif()
    file(READ ${WORK}/${run}.json ${run})
endforeach()
if(NOT bare STREQUAL given)
    message(FATAL_ERROR "rtlab-stat's defaults are not the tests' tolerance (${TOLERANCE}):\n"
                        "without it: ${bare}with it:    ${given}")
endif()
message("${given}")
