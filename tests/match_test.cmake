# match (common/core/dispatch.hpp) decides each kind of a closed set in one place, with no
# default: a match that forgets a kind, or that has a catch-all case, must not compile. The
# complete match must. Each snippet is compiled with -fsyntax-only against the core layer.
#   cmake -DCXX=... -DVIEW=build/layers/core -DWORK=dir -P match_test.cmake
file(MAKE_DIRECTORY ${WORK})
set(head "#include \"core/dispatch.hpp\"\nstruct A {};\nstruct B {};\nint f(const std::variant<A, B>& v) {\n")
set(case_complete "    return rt::match(v, [](const A&) { return 1; }, [](const B&) { return 2; });\n")
set(case_missing "    return rt::match(v, [](const A&) { return 1; });\n")
set(case_catch_all "    return rt::match(v, [](const A&) { return 1; }, [](const auto&) { return 2; });\n")
set(failures 0)
foreach(name complete missing catch_all)
    file(WRITE ${WORK}/match_${name}.cpp "${head}${case_${name}}}\n")
    execute_process(COMMAND ${CXX} -std=c++20 -fsyntax-only -I${VIEW} ${WORK}/match_${name}.cpp
                    RESULT_VARIABLE code ERROR_VARIABLE err)
    if(name STREQUAL "complete")
        if(NOT code EQUAL 0)
            message(SEND_ERROR "a match with a case for every kind does not compile: ${err}")
            math(EXPR failures "${failures} + 1")
        endif()
    elseif(name STREQUAL "missing" AND (code EQUAL 0 OR NOT err MATCHES "a case for every kind"))
        message(SEND_ERROR "a match without a case for B compiles, or fails for another reason: ${err}")
        math(EXPR failures "${failures} + 1")
    elseif(name STREQUAL "catch_all" AND (code EQUAL 0 OR NOT err MATCHES "no catch-all"))
        message(SEND_ERROR "a match with a catch-all case compiles, or fails for another reason: ${err}")
        math(EXPR failures "${failures} + 1")
    endif()
endforeach()
math(EXPR passed "3 - ${failures}")
message("${passed} passed, ${failures} failed")
