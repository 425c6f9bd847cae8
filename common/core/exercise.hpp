#pragma once
// The exception every exercise stub throws, so that an unfinished exercise fails a test
// with a message that names it, rather than crashing or returning garbage.
#include <stdexcept>
#include <string>

namespace rt {

struct NotImplemented : std::logic_error {
    using std::logic_error::logic_error;
};

}  // namespace rt
