// adversarial 2.2: floods its output
// @helpers
#include <cstdio>
// @body
    for (;;) std::fputs("flood flood flood flood flood flood flood flood flood flood flood flood\n", stdout);
