# One golden-image test: render SCENE with CHAPTER at RENDER_ARGS into OUTPUT, check that no
# sample came out NaN or infinite (--stats), compare it with REFERENCE by rtlab-diff within
# TOLERANCE. The diff's report goes to OUTPUT.txt; on failure
# the heatmap stays next to the output as OUTPUT-heatmap.png.
string(REGEX REPLACE "\\.png$" "" stem "${OUTPUT}")
file(REMOVE "${OUTPUT}" "${stem}-heatmap.png" "${stem}.txt")
include(${CMAKE_CURRENT_LIST_DIR}/render_checked.cmake)
render_checked(${OUTPUT} "${stem}.txt" ${RENDER_ARGS})
execute_process(COMMAND ${DIFF} ${REFERENCE} ${OUTPUT} ${TOLERANCE} --heatmap ${stem}-heatmap.png
    RESULT_VARIABLE code OUTPUT_VARIABLE report ERROR_VARIABLE err)
file(WRITE "${stem}.txt" "${report}${err}")
message("${report}${err}")
if(NOT code EQUAL 0)
    message(FATAL_ERROR "${SCENE} differs from ${REFERENCE} past the tolerance; heatmap: ${stem}-heatmap.png")
endif()
file(REMOVE "${stem}-heatmap.png")
