# render_checked(OUTPUT REPORT ARGS...): runs CHAPTER --scene SCENE ARGS... -o OUTPUT --stats
# and fails the calling test unless it exits 0 with no NaN or infinite sample; on a failed
# render, REPORT (the text the grader shows) says why.
function(render_checked output report)
    # REPORT's .uses twin: the student's exercises the render went through (--stats), which
    # the grader names beside a failed comparison.
    string(REGEX REPLACE "\\.txt$" "" uses "${report}")
    set(uses "${uses}.uses")
    file(REMOVE "${uses}")
    # A render that hangs (an exercise that never returns) fails in a minute, not at ctest's
    # timeout: the golden images at the tests' sizes take a second or two, under ASan too.
    execute_process(COMMAND ${CHAPTER} --scene ${SCENE} ${ARGN} -o ${output} --stats TIMEOUT 60
        RESULT_VARIABLE code OUTPUT_VARIABLE stats ERROR_VARIABLE err)
    if(NOT code EQUAL 0)
        if(code MATCHES "timeout")
            set(err "did not finish in 60 s (an exercise that never returns?)")
        elseif(err STREQUAL "")  # killed by a signal: CMake gives its name, e.g. "Segmentation fault"
            set(err "crashed (${code})")
        endif()
        file(WRITE "${report}" "render failed: ${err}")
        message(FATAL_ERROR "render of ${SCENE} (${ARGN}) failed (exit ${code}): ${err}")
    endif()
    string(JSON ran ERROR_VARIABLE no_ran GET "${stats}" your_exercises)
    if(NOT no_ran AND NOT ran STREQUAL "")
        file(WRITE "${uses}" "${ran}")
    endif()
    string(JSON nonfinite GET "${stats}" nonfinite_samples)
    if(NOT nonfinite EQUAL 0)
        message(FATAL_ERROR "render of ${SCENE}: ${nonfinite} samples were NaN or infinite")
    endif()
endfunction()
