# The lab's settings that more than one program reads, stated once: the chapters, and how the
# golden and statistical tests render and judge (book §0.7, §14.6). CMakeLists.txt includes
# this file; the scripts (lab, tools/grade, bench/, tests/*.py) ask it for values, so none
# keeps a copy or parses this text:
#   cmake -DGET=RTLAB_CHAPTERS -P tools/settings.cmake    prints  01 02 ... 18

# Chapters in order. Each NN has chapters/chNN_*/ and solutions/chNN_*.cpp (in a students'
# handout, the compiled tools/reference/ARCH/chNN.o).
set(RTLAB_CHAPTERS 01 02 03 04 05 06 07 08 09 10 11 12 13 14 15 16 17 18)
# The chapters students have exercises for: exercises/chNN_*.cpp, unit tests, golden images and
# a grade. In the lab, all of them; ./lab handout --chapters writes the ones released so far.
set(RTLAB_RELEASED ${RTLAB_CHAPTERS})
# Chapters whose images are noise around a mean: graded by the statistical test (book §14.6)
# against tests/golden/chNN/SCENE.mean.pfm and SCENE.var.pfm, not by a PNG.
set(RTLAB_NOISY_CHAPTERS 14 15 16 17 18)

# Golden images: every scene of every chapter, rendered at fixed settings and compared with
# tests/golden/chNN/SCENE.png (./lab golden renders those at the same settings). The tolerance:
#   each pixel is matched against the best pixel within 1 of it (a one-pixel edge shift is
#   not a failure); a pixel is "over" if a channel differs by more than 8 of 255 levels;
#   pass if at most 0.5% of pixels are over and the RMSE is at most 2 levels.
set(RTLAB_GOLDEN_ARGS --width 160 --height 120 --seed 1 --spp 1)
set(RTLAB_GOLDEN_TOLERANCE --radius 1 --threshold 8 --max-over 0.5 --max-rmse 2)

# Noisy chapters are graded statistically instead (book §14.6): the average of 8 renders
# (RTLAB_STAT_SEEDS) at 64x48 and 16 samples per pixel, each pixel-channel against the
# reference's mean by a t-test with the variance the reference measured for one render at
# these settings (from RTLAB_STAT_VAR_RENDERS renders: --var-renders), and the image fails
# when any p-value is below the Šidák-corrected level, so that a correct render fails with
# probability at most 1 % (alpha 0.01).
set(RTLAB_STAT_SIZE --width 64 --height 48)
set(RTLAB_STAT_ARGS ${RTLAB_STAT_SIZE} --spp 16)
set(RTLAB_STAT_SEEDS 101 102 103 104 105 106 107 108)
set(RTLAB_STAT_VAR_RENDERS 1024)
set(RTLAB_STAT_TOLERANCE --alpha 0.01 --floor 0.004 --var-renders ${RTLAB_STAT_VAR_RENDERS})
# The statistical reference (./lab golden): the mean of 8 renders at 1024 samples per pixel,
# and the variance of RTLAB_STAT_VAR_RENDERS renders at the test's settings, seeds from 1001:
# none of them a seed the tests use. Many renders for the variance: fewer miss the rare
# bright samples of a pixel.
set(RTLAB_STAT_REFERENCE_ARGS ${RTLAB_STAT_SIZE} --spp 1024)
set(RTLAB_STAT_REFERENCE_SEEDS 1 2 3 4 5 6 7 8)
set(RTLAB_STAT_SPREAD_FIRST_SEED 1001)

# Run as a script: print each setting named in GET (one, or several separated by ';'), one
# line each, its items separated by spaces.
if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
    if(NOT GET)
        message(FATAL_ERROR "tools/settings.cmake: give -DGET=NAME, e.g. -DGET=RTLAB_CHAPTERS")
    endif()
    set(lines "")
    foreach(name IN LISTS GET)
        if(NOT name MATCHES "^RTLAB_" OR NOT DEFINED ${name})
            message(FATAL_ERROR "tools/settings.cmake: no setting '${name}'")
        endif()
        string(JOIN " " value ${${name}})
        string(APPEND lines "${value}\n")
    endforeach()
    execute_process(COMMAND ${CMAKE_COMMAND} -E echo_append "${lines}")
endif()
