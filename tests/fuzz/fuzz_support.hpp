#pragma once
// What the libFuzzer targets share: the input as text, and invariants that abort (so that
// libFuzzer keeps the input) when they fail.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace rt::fuzz {

inline std::string text(const std::uint8_t* data, std::size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size);
}

inline void check(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "fuzz invariant failed: %s\n", what);
    std::abort();
}

// The lab's promise for a message: one line, not empty.
inline void one_line(const char* message) {
    check(*message != '\0', "message is empty");
    check(std::strchr(message, '\n') == nullptr, "message is more than one line");
}

}  // namespace rt::fuzz
