// adversarial 2.2: opens a socket and tries to reach the machine's loopback and the world;
// returns true (and a wrong root) only if it got through
// @helpers
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>
// @body
    const int s = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(22);
    to.sin_addr.s_addr = htonl(0x7f000001);
    const bool through = s >= 0 && connect(s, reinterpret_cast<sockaddr*>(&to), sizeof to) == 0;
    if (s >= 0) close(s);
    t_near = t_far = 0;
    return through;
