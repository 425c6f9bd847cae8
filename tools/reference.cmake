# A students' handout (./lab handout, tools/handout.py) has no solutions/: the reference bodies
# come compiled, one relocatable object per chapter and processor, in tools/reference/ARCH/chNN.o,
# made by the lab's compiler without link-time optimisation (its bitcode is tied to one
# compiler version), without -march=native, without debug information, source paths or local
# symbol names. tools/reference/BUILT_WITH says which compiler made them: the oldest this
# handout can link with. A program links them exactly as the lab links solutions/: a chapter
# the student has not written renders and grades with the reference's bodies.
set(rtlab_reference_dir ${PROJECT_SOURCE_DIR}/tools/reference/${CMAKE_SYSTEM_PROCESSOR})
file(STRINGS ${PROJECT_SOURCE_DIR}/tools/reference/BUILT_WITH rtlab_built_with LIMIT_COUNT 1)
if(NOT IS_DIRECTORY ${rtlab_reference_dir})
    file(GLOB rtlab_arches LIST_DIRECTORIES true RELATIVE ${PROJECT_SOURCE_DIR}/tools/reference
         ${PROJECT_SOURCE_DIR}/tools/reference/*)
    list(REMOVE_ITEM rtlab_arches BUILT_WITH)
    string(REPLACE ";" ", " rtlab_arches "${rtlab_arches}")
    message(FATAL_ERROR "This handout's reference bodies are compiled for ${rtlab_arches}, not for "
                        "${CMAKE_SYSTEM_PROCESSOR}: ask your instructor for a handout made for it")
endif()
# "GNU 12": objects of GCC 12 link with GCC 12 or later, or with clang on the same libstdc++.
string(REGEX MATCH "^(GNU|Clang) ([0-9]+)" rtlab_built_ok "${rtlab_built_with}")
set(rtlab_built_major ${CMAKE_MATCH_2})
if(NOT CMAKE_CXX_COMPILER_ID MATCHES "^(GNU|Clang)$"
   OR (CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS rtlab_built_major))
    message(FATAL_ERROR "This handout's reference bodies were compiled by ${rtlab_built_with} and cannot be linked "
                        "with ${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION}: use GCC ${rtlab_built_major} or "
                        "later (Debian 12's g++ or newer)")
endif()
if(NOT RTLAB_REAL STREQUAL "double")
    message(FATAL_ERROR "This handout's reference bodies are compiled for Real=double: RTLAB_REAL=${RTLAB_REAL} "
                        "cannot link them")
endif()

function(rtlab_reference_object ch)
    if(NOT EXISTS ${rtlab_reference_dir}/ch${ch}.o)
        message(FATAL_ERROR "tools/reference/${CMAKE_SYSTEM_PROCESSOR}/ch${ch}.o is missing: this handout is incomplete")
    endif()
    add_library(rtlab_solution_${ch} OBJECT IMPORTED GLOBAL)
    set_target_properties(rtlab_solution_${ch} PROPERTIES IMPORTED_OBJECTS ${rtlab_reference_dir}/ch${ch}.o)
endfunction()
