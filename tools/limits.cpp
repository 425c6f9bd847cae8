// rtlab-limits: prints the limits of common/geometry/limits.hpp as JSON, so that
// tests/schema_test.py can hold the JSON Schema to the one table.
#include "geometry/limits.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>

int main() {
    nlohmann::json all = nlohmann::json::array();
    for (const auto& r : rt::limits::all)
        all.push_back({{"name", r.name}, {"min", r.min}, {"max", r.max}, {"what", r.what}, {"schema", r.schema}});
    std::printf("%s\n", all.dump(1).c_str());
}
