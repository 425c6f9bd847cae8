# The book's diagrams (tools/figures/). Included by tests/CMakeLists.txt, it adds the test
# `figures`, which runs this same file as a script (cmake -P): every description renders,
# each SVG is well-formed XML, there are at least RTLAB_FIGURES_MIN of them, the book shows
# every one and every chNN/figures/*.svg it shows has a description; and bad descriptions
# are refused with one line and exit 2, writing nothing.
if(NOT CMAKE_SCRIPT_MODE_FILE)
    # How many diagrams the book has at least: raised as figures are added, never lowered.
    set(RTLAB_FIGURES_MIN 24)
    add_test(NAME figures
        COMMAND ${CMAKE_COMMAND} -DFIGURES=$<TARGET_FILE:rtlab-figures> -DROOT=${PROJECT_SOURCE_DIR}
            -DWORK=${PROJECT_BINARY_DIR}/figures-test -DPYTHON=${Python3_EXECUTABLE} -DMIN=${RTLAB_FIGURES_MIN}
            -P ${CMAKE_CURRENT_LIST_FILE})
    set_tests_properties(figures PROPERTIES LABELS "tools")
    return()
endif()

cmake_policy(SET CMP0057 NEW)  # if(IN_LIST) in script mode
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# Every description renders.
execute_process(COMMAND ${FIGURES} --root ${ROOT} --out ${WORK}/out RESULT_VARIABLE code ERROR_VARIABLE err
                OUTPUT_QUIET)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "rtlab-figures failed (exit ${code}): ${err}")
endif()
execute_process(COMMAND ${FIGURES} --root ${ROOT} --list OUTPUT_VARIABLE listed RESULT_VARIABLE code)
string(STRIP "${listed}" listed)
string(REPLACE "\n" ";" listed "${listed}")
list(LENGTH listed count)
if(count LESS MIN)
    message(SEND_ERROR "${count} figures, fewer than the ${MIN} the book should have (RTLAB_FIGURES_MIN)")
endif()
set(files "")
foreach(name IN LISTS listed)
    if(NOT EXISTS ${WORK}/out/${name})
        message(SEND_ERROR "--list names ${name}, which the render did not write")
    endif()
    list(APPEND files ${WORK}/out/${name})
endforeach()

# Well-formed XML whose root is an <svg> with a view box (so that it scales on a small screen).
execute_process(COMMAND ${PYTHON} -c [[
import sys, xml.etree.ElementTree as E
for f in sys.argv[1:]:
    root = E.parse(f).getroot()
    if root.tag != "{http://www.w3.org/2000/svg}svg" or "viewBox" not in root.attrib:
        sys.exit(f + ": not an <svg> with a viewBox")
]] ${files} RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(SEND_ERROR "not well-formed SVG: ${err}")
endif()

# The book shows each one, and shows no diagram that has no description.
file(GLOB chapters ${ROOT}/book/*.md)
set(shown "")
foreach(md IN LISTS chapters)
    file(READ ${md} text)
    string(REGEX MATCHALL "ch[0-9][0-9]/figures/[^)\n ]+\\.svg" refs "${text}")
    list(APPEND shown ${refs})
endforeach()
foreach(name IN LISTS listed)
    if(NOT name IN_LIST shown)
        message(SEND_ERROR "${name} is drawn but the book does not show it: add ![caption](../${name}) to its chapter")
    endif()
endforeach()
foreach(name IN LISTS shown)
    if(NOT name IN_LIST listed)
        message(SEND_ERROR "the book shows ${name}, which has no description chapters/${name}.json")
    endif()
endforeach()

# Bad descriptions: exit 2, one line naming the file and the key, nothing written.
set(bad_cases
    "radius|{\"kind\": \"ray-sphere\", \"caption\": \"c\", \"center\": [0, 0, 0], \"radius\": -1, \"rays\": []}"
    "colour|{\"kind\": \"ray-sphere\", \"caption\": \"c\", \"center\": [0, 0, 0], \"radius\": 1, \"rays\": [], \"colour\": 1}"
    "kind|{\"kind\": \"teapot\", \"caption\": \"c\"}"
    "not valid JSON|{\"kind\": \"ray-sphere\","
    "square number|{\"kind\": \"pixel-samples\", \"caption\": \"c\", \"samples\": 10, \"seed\": 0, \"pixel\": 0}"
    "not in front of the triangle|{\"kind\": \"grid-trap\", \"caption\": \"c\", \"triangle\": [[4, -2, -1.5], [4, 2, -1.5], [0, 0, 2.5]], \"sphere\": {\"center\": [3.5, 0, -0.3], \"radius\": 0.4}, \"density\": 50, \"ray\": {\"origin\": [-1, 0, -0.3], \"direction\": [1, 0, 0], \"t_end\": 5}}"
    "cut once, across x|{\"kind\": \"bsp-cases\", \"caption\": \"c\", \"spheres\": [{\"center\": [0, -1, 0], \"radius\": 0.5}, {\"center\": [0, 1, 0], \"radius\": 0.5}], \"rays\": []}")
set(n 0)
foreach(case IN LISTS bad_cases)
    string(REGEX REPLACE "\\|.*" "" expect "${case}")
    string(REGEX REPLACE "^[^|]*\\|" "" json "${case}")
    math(EXPR n "${n} + 1")
    set(bad_root ${WORK}/bad${n})
    file(WRITE ${bad_root}/chapters/ch02_spheres/figures/bad.json "${json}")
    execute_process(COMMAND ${FIGURES} --root ${bad_root} --out ${bad_root}/out RESULT_VARIABLE code
                    ERROR_VARIABLE err OUTPUT_QUIET)
    string(STRIP "${err}" err)
    string(FIND "${err}" "\n" newline)
    if(NOT code EQUAL 2 OR NOT newline EQUAL -1 OR NOT err MATCHES "^chapters/ch02_spheres/figures/bad.json:"
       OR NOT err MATCHES "${expect}")
        message(SEND_ERROR "bad description ${n} (${expect}): exit ${code}, message '${err}'")
    endif()
    if(EXISTS ${bad_root}/out/ch02/figures/bad.svg)
        message(SEND_ERROR "bad description ${n} (${expect}) wrote its SVG")
    endif()
endforeach()
message(STATUS "${count} figures, well-formed and each shown by the book; ${n} bad descriptions refused")
