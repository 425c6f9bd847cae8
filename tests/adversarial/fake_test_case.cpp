// adversarial 2.2: registers test cases of its own, one with the name of a real 2.2 test
// @helpers
#include <doctest/doctest.h>
TEST_CASE("2.2 course exercise 1, stable roots") {}
TEST_CASE("free points") {}
// @body
    return false;
