# The lab explorer (common/app/explore*, tools/explore/): its server over HTTP, and its page in
# a real browser. Included by tests/CMakeLists.txt.

# Endpoints: the page and three.js served, frames converging, picks equal to --pick, bad
# requests refused in one line, a scene error as the loader words it, concurrent requests.
add_test(NAME explore_endpoints
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/explore_endpoints_test.py ${PROJECT_SOURCE_DIR}
        ${PROJECT_BINARY_DIR}/bin ${PROJECT_BINARY_DIR}/explore-endpoints)
set_tests_properties(explore_endpoints PROPERTIES LABELS "cli;explore" TIMEOUT 600)

# What it refuses (book §0.11): no token or a wrong one, foreign Hosts and Origins, bodies over
# the limit, meshes outside its folders (never opened), markup in names; and a load of 2,000
# mixed requests from 8 clients, after which its threads and memory are back where they were.
add_test(NAME explore_gate
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/explore_gate_test.py ${PROJECT_SOURCE_DIR}
        ${PROJECT_BINARY_DIR}/bin ${PROJECT_BINARY_DIR}/explore-gate)
set_tests_properties(explore_gate PROPERTIES LABELS "cli;explore" TIMEOUT 600)
add_test(NAME explore_load
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/explore_load_test.py ${PROJECT_SOURCE_DIR}
        ${PROJECT_BINARY_DIR}/bin ${PROJECT_BINARY_DIR}/explore-load $<$<BOOL:${RTLAB_SANITIZE}>:sanitized>)
# Alone: its memory and thread counts are of the server under its own load.
set_tests_properties(explore_load PROPERTIES LABELS "cli;explore" TIMEOUT 600 RUN_SERIAL ON)

# The page in Debian's chromium, headless, driven by python3-selenium and chromium-driver
# (Debian's python3 has the module; a python3 of another install may not).
find_program(RTLAB_DEBIAN_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH REQUIRED)
add_test(NAME explore_browser
    COMMAND ${RTLAB_DEBIAN_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/explore_browser_test.py ${PROJECT_SOURCE_DIR}
        ${PROJECT_BINARY_DIR}/bin ${PROJECT_BINARY_DIR}/explore-browser)
# One browser at a time: it takes both cores while it starts.
set_tests_properties(explore_browser PROPERTIES LABELS "cli;explore" TIMEOUT 600 RUN_SERIAL ON)
