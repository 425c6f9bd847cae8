// adversarial 2.2: prints doctest's own summary line, then ends the program with _Exit(0)
// @helpers
#include <cstdio>
#include <cstdlib>
// @body
    std::printf("[doctest] test cases: 99 | 99 passed | 0 failed | 0 skipped\n");
    std::printf("[doctest] Status: SUCCESS!\n");
    std::fflush(stdout);
    std::_Exit(0);
