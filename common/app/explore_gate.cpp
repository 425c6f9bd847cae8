#include "app/explore_gate.hpp"

#include "core/limits.hpp"
#include "core/text.hpp"

#include <httplib.h>
#include <openssl/crypto.h>
#include <sys/random.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace rt {

namespace {

// The names this server is reached by: the address it listens on, the name browsers give it,
// and the IPv6 loopback a browser may try first for "localhost".
constexpr std::array kLoopback{"127.0.0.1", "localhost", "[::1]"};
// The header the page sends the token in (tools/explore/explore.js).
constexpr const char* kTokenHeader = "X-Rtlab-Token";

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

// The token compared in a time that depends on its length only, not on how many of its
// first characters a guess got right (OpenSSL's CRYPTO_memcmp: a loop the compiler cannot
// cut short). The length is no secret: every token has 32 digits.
bool same_token(const std::string& given, const std::string& token) {
    return given.size() == token.size() && CRYPTO_memcmp(given.data(), token.data(), token.size()) == 0;
}

}  // namespace

std::string new_explore_token() {
    std::array<unsigned char, 16> bytes{};
    std::size_t got = 0;
    while (got < bytes.size()) {
        const ssize_t n = getrandom(bytes.data() + got, bytes.size() - got, 0);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw std::runtime_error(std::string("no random token: getrandom: ") + std::strerror(errno));
        got += std::size_t(n);
    }
    static constexpr char hex[] = "0123456789abcdef";
    std::string token;
    for (const unsigned char b : bytes) {
        token += hex[b >> 4];
        token += hex[b & 15];
    }
    return token;
}

ExploreGate::ExploreGate(int port, std::string token) : token_(std::move(token)) {
    const std::string scheme = "http://", p = std::string(":").append(std::to_string(port));
    for (const std::string host : kLoopback) {
        hosts_.push_back(host + p);
        origins_.push_back(scheme + hosts_.back());
        if (port == 80) {  // the default port: browsers leave it out
            hosts_.push_back(host);
            origins_.push_back(scheme + host);
        }
    }
}

std::string ExploreGate::address() const {
    return origins_.front() + "/" + (token_.empty() ? "" : "?token=" + token_);
}

std::optional<Refusal> ExploreGate::check(const httplib::Request& req, bool page_file) const {
    const auto one = [&](const char* key) -> std::optional<Refusal> {
        if (req.get_header_value_count(key) > 1) return Refusal{400, std::string("more than one ") + key + " header"};
        return std::nullopt;
    };
    for (const char* key : {"Host", "Origin", kTokenHeader, "Content-Length"})
        if (auto refused = one(key)) return refused;

    // Host: a page whose own name was made to point at 127.0.0.1 sends its name, not ours.
    const std::string host = req.get_header_value("Host");
    if (std::find(hosts_.begin(), hosts_.end(), lower(host)) == hosts_.end())
        return Refusal{403,
                       (host.empty() ? std::string("no Host header") : "Host '" + host + "' is not this explorer") +
                           ": it answers only " + or_list(hosts_) +
                           " (a page of another site reaches it by another name: DNS rebinding)"};
    // Origin: browsers send it with every request that changes something, and with any request
    // a page makes to another site's server. Programs (curl, the tests) send none.
    if (req.has_header("Origin")) {
        const std::string origin = req.get_header_value("Origin");
        if (std::find(origins_.begin(), origins_.end(), lower(origin)) == origins_.end())
            return Refusal{403, "Origin '" + origin + "' is not this explorer's page (" + origins_.front() +
                                    "): a page of another site may not drive it"};
    }
    if (!page_file && !token_.empty()) {
        // An empty header is no token: Debian 12's cpp-httplib (0.11) drops a header with no
        // value, Debian 13's (0.18) keeps it; either way the page without its token says so.
        const std::string sent = req.has_header(kTokenHeader) ? req.get_header_value(kTokenHeader) : "";
        const char* problem = sent.empty() ? "no token" : !same_token(sent, token_) ? "wrong token" : nullptr;
        if (problem)
            return Refusal{403, std::string(problem) + ": open the address the explorer printed (" + origins_.front() +
                                    "/?token=...); its page sends the token with every request"};
    }
    // The body: its size known before a byte of it is read, and no larger than a scene file.
    if (req.has_header("Transfer-Encoding"))
        return Refusal{411, "a body must give its size (Content-Length): chunked bodies are refused"};
    if (req.has_header("Content-Length")) {
        const std::string text = req.get_header_value("Content-Length");
        const char* const finish = text.data() + text.size();
        unsigned long long size = 0;
        const auto [end, error] = std::from_chars(text.data(), finish, size);
        const bool huge = error == std::errc::result_out_of_range;
        if (text.empty() || end != finish || (error != std::errc() && !huge))
            return Refusal{400, "Content-Length '" + text + "' is not a whole number"};
        if (huge || !limits::contains(limits::scene_file_bytes, double(size)))
            return Refusal{413, "the body is refused before it is read: " +
                                    limits::refuse(limits::scene_file_bytes,
                                                   huge ? std::strtod(text.c_str(), nullptr) : double(size))};
    }
    return std::nullopt;
}

}  // namespace rt
