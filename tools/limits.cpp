// rtlab-limits: prints the scene limits of common/geometry/limits.hpp as JSON, so that
// tests/schema_test.py can hold the JSON Schema to the one table.
#include "geometry/limits.hpp"

#include <cstdio>

int main() {
    std::printf("[");
    bool first = true;
    for (const auto& r : rt::limits::all) {
        std::printf("%s\n {\"name\": \"%s\", \"min\": %lld, \"max\": %lld, \"schema\": \"%s\"}", first ? "" : ",",
                    r.name, r.min, r.max, r.schema);
        first = false;
    }
    std::printf("\n]\n");
}
