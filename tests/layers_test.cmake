# The layering of common/ is enforced by the compiler: in each layer's view (build/layers/L)
# only the layers L sees exist. For every layer, include a header of each other layer: one it
# does not see must fail ("No such file|file not found"), one it sees must compile (the view
# works; the build already compiles every header inside its own layer). Preprocessing is
# enough for both: it finds every file a header includes, or names the one it cannot.
#   cmake -DCXX=... -DVIEWS=build/layers -DSOURCE=common "-DLAYERS=core=core;geometry=geometry,core;..."
#         -DWORK=dir -P layers_test.cmake
cmake_policy(SET CMP0057 NEW)  # if(IN_LIST) in script mode
file(MAKE_DIRECTORY ${WORK})
set(failures 0)
set(checks 0)
set(names "")
foreach(entry IN LISTS LAYERS)
    string(REGEX REPLACE "=.*" "" name "${entry}")
    list(APPEND names ${name})
endforeach()
foreach(entry IN LISTS LAYERS)
    string(REGEX REPLACE "=.*" "" layer "${entry}")
    string(REGEX REPLACE ".*=" "" sees "${entry}")
    string(REPLACE "," ";" sees "${sees}")
    foreach(other IN LISTS names)
        file(GLOB headers RELATIVE ${SOURCE} ${SOURCE}/${other}/*.hpp)
        list(GET headers 0 header)
        file(WRITE ${WORK}/${layer}_sees_${other}.cpp "#include \"${header}\"\n")
        execute_process(COMMAND ${CXX} -std=c++20 -E -I${VIEWS}/${layer} ${INCLUDES}
                                ${WORK}/${layer}_sees_${other}.cpp
                        RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
        math(EXPR checks "${checks} + 1")
        if(NOT other IN_LIST sees)
            if(code EQUAL 0 OR NOT err MATCHES "No such file|file not found")
                message(SEND_ERROR "${layer} can include ${header}, from a layer it does not use")
                math(EXPR failures "${failures} + 1")
            endif()
        elseif(NOT code EQUAL 0)
            message(SEND_ERROR "${layer} cannot include ${header}: ${err}")
            math(EXPR failures "${failures} + 1")
        endif()
    endforeach()
endforeach()
math(EXPR passed "${checks} - ${failures}")
message("${passed} passed, ${failures} failed")
