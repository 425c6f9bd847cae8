# Fails if a scene that CHAPTER lists has no reference image in GOLDEN_DIR (SCENE.png, or
# SCENE.mean.pfm for a noisy chapter).
execute_process(COMMAND ${CHAPTER} --list-scenes RESULT_VARIABLE code OUTPUT_VARIABLE scenes)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "${CHAPTER} --list-scenes failed")
endif()
string(REPLACE "\n" ";" scenes "${scenes}")
foreach(scene IN LISTS scenes)
    # A noisy chapter's reference is a mean and a variance (book §14.6).
    if(scene AND NOT EXISTS "${GOLDEN_DIR}/${scene}.png" AND NOT EXISTS "${GOLDEN_DIR}/${scene}.mean.pfm")
        message(FATAL_ERROR "scene ${scene} has no golden image ${GOLDEN_DIR}/${scene}.png (./lab golden)")
    endif()
    if(scene AND EXISTS "${GOLDEN_DIR}/${scene}.mean.pfm" AND NOT EXISTS "${GOLDEN_DIR}/${scene}.var.pfm")
        message(FATAL_ERROR "scene ${scene} has a mean but no variance ${GOLDEN_DIR}/${scene}.var.pfm (./lab golden)")
    endif()
endforeach()
