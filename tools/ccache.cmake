# Compiles go through ccache where it is installed (./lab test installs it), for every build
# of the lab whatever starts it (./lab, tools/grade, a preset by hand): a rebuild, a cleaned
# build directory or a second copy of the lab then costs no compile.
#   CCACHE_BASEDIR: paths are hashed relative to the checkout, so another clone hits too.
#   CCACHE_SLOPPINESS=time_macros: pcg_extras.hpp (included by every file that samples) puts
#   __DATE__ __TIME__ into a seed the lab never uses; without it, ccache would miss on all
#   those files. pch_defines: the exercise files' precompiled headers (CMakeLists.txt) are
#   cached, and so are the files compiled with them (ccache refuses both without it; no
#   exercise file defines a macro before its headers, which is what it would miss).
#   Absolute paths in a file's flags would make each copy of the lab miss: app/lab_paths.hpp.
#   CCACHE_NOHASHDIR=true: with debug information (the sanitizer presets' -g1) ccache would key
#   each object on the folder it is compiled in, so every clone compiled the asan and tsan
#   builds again; the price is that an object's line tables may name the folder of the copy
#   that compiled it first (the file names and lines a sanitizer prints are the same).
# A launcher given on the command line wins, except plain "ccache" (what an older lab put in
# the cache, and a hand-made build may give): that one gets these settings too.
find_program(RTLAB_CCACHE_PROGRAM ccache)
if(RTLAB_CCACHE_PROGRAM AND (NOT CMAKE_CXX_COMPILER_LAUNCHER OR CMAKE_CXX_COMPILER_LAUNCHER STREQUAL "ccache"))
    set(CMAKE_CXX_COMPILER_LAUNCHER env CCACHE_BASEDIR=${PROJECT_SOURCE_DIR} CCACHE_SLOPPINESS=time_macros,pch_defines
        CCACHE_NOHASHDIR=true ${RTLAB_CCACHE_PROGRAM})
endif()
# Compiles outside the build's own rules (tools/handout.py's reference objects) take the same
# launcher from CMakeCache.txt.
set(RTLAB_CXX_LAUNCHER "${CMAKE_CXX_COMPILER_LAUNCHER}" CACHE INTERNAL "the compiler launcher, for compiles outside the build's rules")
