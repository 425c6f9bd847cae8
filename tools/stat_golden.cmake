# One statistical golden test (book §14.6): render SCENE with CHAPTER at RENDER_ARGS (plus
# EXTRA_ARGS) once per seed of SEEDS as PFM into OUTDIR, check that no sample was NaN or
# infinite, and test the renders against the reference MEAN and VAR with STAT (rtlab-stat).
# EXPECT pass: the test must pass. EXPECT fail: it must fail (a planted sampler bug).
# With GROUPS = G > 1, the seeds are G groups of SEEDS' length (each its own seeds) and the
# test passes when at most MAX_FALSE_ALARMS of them fail: the false-alarm rate, measured.
include(${CMAKE_CURRENT_LIST_DIR}/render_checked.cmake)
if(NOT GROUPS)
    set(GROUPS 1)
endif()
file(MAKE_DIRECTORY ${OUTDIR})
file(REMOVE ${OUTDIR}/${SCENE}.txt ${OUTDIR}/${SCENE}-yours.png ${OUTDIR}/${SCENE}-map.png ${OUTDIR}/${SCENE}.json
     ${OUTDIR}/${SCENE}-reference.png)
# The reference picture first, so that the grade report shows it even when a render fails
# (an unfinished exercise): the reference's mean tested against itself writes it.
execute_process(COMMAND ${STAT} test ${MEAN} ${VAR} ${MEAN} ${MEAN} --reference-image ${OUTDIR}/${SCENE}-reference.png
    RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "rtlab-stat could not read the reference of ${SCENE}: ${err}")
endif()
list(LENGTH SEEDS per_group)
list(GET SEEDS 0 first_seed)
set(failures 0)
math(EXPR last_group "${GROUPS} - 1")
foreach(group RANGE ${last_group})
    set(images "")
    math(EXPR last "${per_group} - 1")
    foreach(k RANGE ${last})
        math(EXPR seed "${first_seed} + ${group} * ${per_group} + ${k}")
        set(image ${OUTDIR}/${SCENE}-${seed}.pfm)
        render_checked(${image} ${OUTDIR}/${SCENE}.txt ${RENDER_ARGS} ${EXTRA_ARGS} --seed ${seed})
        list(APPEND images ${image})
    endforeach()
    execute_process(COMMAND ${STAT} test ${MEAN} ${VAR} ${images} ${TOLERANCE} --map ${OUTDIR}/${SCENE}-map.png
                            --json ${OUTDIR}/${SCENE}.json --average ${OUTDIR}/${SCENE}-yours.png
                            --reference-image ${OUTDIR}/${SCENE}-reference.png
        RESULT_VARIABLE code OUTPUT_VARIABLE report ERROR_VARIABLE err)
    message("${report}${err}")
    file(WRITE ${OUTDIR}/${SCENE}.txt "${report}${err}")
    if(NOT code EQUAL 0 AND NOT code EQUAL 1)
        message(FATAL_ERROR "rtlab-stat failed on ${SCENE}: ${err}")
    endif()
    if(code EQUAL 1)
        math(EXPR failures "${failures} + 1")
    endif()
    file(REMOVE ${images})
endforeach()
if(GROUPS GREATER 1)
    message("${failures} of ${GROUPS} correct renders failed (allowed: ${MAX_FALSE_ALARMS})")
    if(failures GREATER MAX_FALSE_ALARMS)
        message(FATAL_ERROR "false alarms: ${failures} of ${GROUPS} correct renders of ${SCENE} failed")
    endif()
elseif(EXPECT STREQUAL "fail" AND failures EQUAL 0)
    message(FATAL_ERROR "${SCENE} with ${EXTRA_ARGS} passed: the statistical test missed a planted sampler bug")
elseif(EXPECT STREQUAL "pass" AND failures GREATER 0)
    message(FATAL_ERROR "${SCENE} differs from its reference ${MEAN}; map of failing pixels: ${OUTDIR}/${SCENE}-map.png")
endif()
