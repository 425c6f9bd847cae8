// adversarial 2.2: ends the program with std::exit(0) inside the test
// @helpers
#include <cstdlib>
// @body
    std::exit(0);
