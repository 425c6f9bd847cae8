// adversarial 2.2: writes "passed" records in the verdict channel's shape to every descriptor,
// and to every file the grader might read
// @helpers
#include <string>
#include <unistd.h>
// @body
    for (int fd = 0; fd < 256; ++fd)
        for (int i = 1; i < 40; ++i) {
            const std::string line = std::string(64, '0') + " " + std::to_string(getpid()) + " end " +
                                     std::to_string(i) + " passed\n";
            (void)!write(fd, line.data(), line.size());
        }
    return false;
