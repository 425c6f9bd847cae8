// adversarial 2.2: allocates without end, touching every page
// @helpers
#include <cstdlib>
#include <cstring>
// @body
    for (;;) {
        void* p = std::malloc(64 << 20);
        if (p) std::memset(p, 1, 64 << 20);
    }
