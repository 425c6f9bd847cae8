// adversarial 2.2: aborts
// @helpers
#include <cstdlib>
// @body
    std::abort();
