// adversarial 2.2: defines the C library's read(), to steal the harness's secret
// @helpers
#include <sys/syscall.h>
#include <unistd.h>
extern "C" ssize_t read(int fd, void* buf, size_t n) { return syscall(SYS_read, fd, buf, n); }
// @body
    return false;
