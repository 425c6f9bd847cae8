// adversarial 2.2: forks a child that leaves the process group and sleeps, holding every
// descriptor it inherited, then answers wrongly
// @helpers
#include <unistd.h>
// @body
    if (fork() == 0) {
        setsid();
        sleep(100000);
        _exit(0);
    }
    return false;
