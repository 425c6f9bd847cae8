#pragma once
// Who may drive the explorer (book §0.11). Its server listens on 127.0.0.1, which every
// program on the machine can reach, and so can every page the student's browser shows: a
// site's script may send requests there, and by DNS rebinding (its own name made to point at
// 127.0.0.1) read the answers too. The gate lets through what Jupyter's server does: requests
// that name this server in their Host, come from its own page if from a page at all, and carry
// the token the explorer printed; and bodies no larger than a scene file.
#include <optional>
#include <string>
#include <vector>

namespace httplib {
struct Request;
}

namespace rt {

// A request turned away: the HTTP status and the one line that says why.
struct Refusal {
    int status;
    std::string reason;
};

class ExploreGate {
public:
    // `token` empty: --no-token (for tests), where any program on the machine may drive the
    // explorer; Host and Origin are still checked, so a page of another site still may not.
    ExploreGate(int port, std::string token);

    // Nothing, or why `req` is refused, checked before its body is read: its Host (127.0.0.1,
    // localhost or [::1], with this port); its Origin, when it has one (this server's page);
    // its token (the X-Rtlab-Token header), except for the page's own files (`page_file`),
    // which hold nothing of the session; and its body's declared size (limits::scene_file_bytes).
    std::optional<Refusal> check(const httplib::Request& req, bool page_file) const;

    // What the explorer prints: http://127.0.0.1:PORT/?token=TOKEN.
    std::string address() const;

private:
    std::string token_;
    std::vector<std::string> hosts_;    // "127.0.0.1:PORT", ...
    std::vector<std::string> origins_;  // "http://127.0.0.1:PORT", ...
};

// A new token: 128 bits from the operating system's random source (getrandom(2)), as 32
// hexadecimal digits. Throws std::runtime_error if there is none.
std::string new_explore_token();

}  // namespace rt
