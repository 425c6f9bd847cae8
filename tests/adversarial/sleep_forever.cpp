// adversarial 2.2: never returns
// @helpers
#include <unistd.h>
// @body
    for (;;) pause();
