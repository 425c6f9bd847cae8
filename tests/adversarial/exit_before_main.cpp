// adversarial 2.2: ends every program that links it before main, with exit status 0
// @helpers
#include <cstdlib>
namespace {
const int gone = (std::exit(0), 0);
}  // namespace
// @body
    return false;
