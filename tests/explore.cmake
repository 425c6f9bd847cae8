# The lab explorer (common/app/explore*, tools/explore/): its server over HTTP, and its page in
# a real browser. Included by tests/CMakeLists.txt.

# Endpoints: the page and three.js served, frames converging, picks equal to --pick, bad
# requests refused in one line, a scene error as the loader words it, concurrent requests.
add_test(NAME explore_endpoints
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/explore_endpoints_test.py ${PROJECT_SOURCE_DIR}
        ${PROJECT_BINARY_DIR}/bin ${PROJECT_BINARY_DIR}/explore-endpoints)
set_tests_properties(explore_endpoints PROPERTIES LABELS "cli;explore" TIMEOUT 600)

# The page in Debian's chromium, headless, driven by python3-selenium and chromium-driver
# (Debian's python3 has the module; a python3 of another install may not).
find_program(RTLAB_DEBIAN_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH REQUIRED)
add_test(NAME explore_browser
    COMMAND ${RTLAB_DEBIAN_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/explore_browser_test.py ${PROJECT_SOURCE_DIR}
        ${PROJECT_BINARY_DIR}/bin ${PROJECT_BINARY_DIR}/explore-browser)
# One browser at a time: it takes both cores while it starts.
set_tests_properties(explore_browser PROPERTIES LABELS "cli;explore" TIMEOUT 600 RUN_SERIAL ON)
