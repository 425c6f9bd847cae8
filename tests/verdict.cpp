#include "verdict.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

// Static and unnamed: no symbol a student's code could name holds the secret.
constexpr int kSecretLength = 64;
char secret[kSecretLength + 1];
int channel = -1;

// A malformed RTLAB_VERDICT leaves the channel closed: the grader then sees no record and
// counts nothing as passed, which is the safe side. This runs before the C library has set up
// getenv(), so it reads the environment it is given, and takes the variable out of it (the
// same array becomes `environ`).
void open_channel(int, char**, char** envp) {
    static constexpr char kName[] = "RTLAB_VERDICT=";
    const char* spec = nullptr;
    for (char** e = envp; e && *e; ++e)
        if (std::strncmp(*e, kName, sizeof kName - 1) == 0) {
            spec = *e + sizeof kName - 1;
            for (char** rest = e; *rest; ++rest) rest[0] = rest[1];
            break;
        }
    if (!spec) return;
    int from = -1, to = -1;
    if (std::sscanf(spec, "%d,%d", &from, &to) != 2 || from < 0 || to < 0) return;
    int got = 0;
    while (got < kSecretLength) {
        const ssize_t n = read(from, secret + got, kSecretLength - got);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        got += int(n);
    }
    close(from);
    if (got != kSecretLength) return;
    secret[kSecretLength] = '\0';
    // A program the student's code starts with exec() does not get the channel.
    fcntl(to, F_SETFD, FD_CLOEXEC);
    channel = to;
    // The first record names the harness's process: no code of the student's has run yet, so
    // no fork of it can be taken for the program.
    rt::verdict::record("begin");
}

// Before every static constructor of the program (the student's too), in link order; a
// .preinit_array of a student's own is refused before linking (tools/grading/symbols.py).
[[gnu::section(".preinit_array"), gnu::used]] void (*const preinit)(int, char**, char**) = open_channel;

}  // namespace

namespace rt::verdict {

bool listening() {
    return channel >= 0;
}

void record(const std::string& what) {
    if (channel < 0) return;
    std::string line = std::string(secret) + ' ' + std::to_string(getpid()) + ' ' + what;
    std::replace(line.begin(), line.end(), '\n', ' ');
    line += '\n';
    // One write() on a file opened for appending: records of other processes never cut it.
    const char* p = line.data();
    std::size_t left = line.size();
    while (left > 0) {
        const ssize_t n = write(channel, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        p += n;
        left -= std::size_t(n);
    }
}

}  // namespace rt::verdict
