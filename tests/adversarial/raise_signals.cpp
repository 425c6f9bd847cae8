// adversarial 2.2: raises SIGSEGV, then SIGKILL on itself
// @helpers
#include <csignal>
// @body
    std::raise(SIGSEGV);
    std::raise(SIGKILL);
    return false;
