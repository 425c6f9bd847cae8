# One golden-image test: render SCENE with CHAPTER at RENDER_ARGS into OUTPUT, compare it with
# REFERENCE by rtlab-diff within TOLERANCE. The diff's report goes to OUTPUT.txt; on failure
# the heatmap stays next to the output as OUTPUT-heatmap.png.
string(REGEX REPLACE "\\.png$" "" stem "${OUTPUT}")
file(REMOVE "${OUTPUT}" "${stem}-heatmap.png" "${stem}.txt")
execute_process(COMMAND ${CHAPTER} --scene ${SCENE} ${RENDER_ARGS} -o ${OUTPUT}
    RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    file(WRITE "${stem}.txt" "render failed: ${err}")
    message(FATAL_ERROR "render of ${SCENE} failed (exit ${code}): ${err}")
endif()
execute_process(COMMAND ${DIFF} ${REFERENCE} ${OUTPUT} ${TOLERANCE} --heatmap ${stem}-heatmap.png
    RESULT_VARIABLE code OUTPUT_VARIABLE report ERROR_VARIABLE err)
file(WRITE "${stem}.txt" "${report}${err}")
message("${report}${err}")
if(NOT code EQUAL 0)
    message(FATAL_ERROR "${SCENE} differs from ${REFERENCE} past the tolerance; heatmap: ${stem}-heatmap.png")
endif()
file(REMOVE "${stem}-heatmap.png")
