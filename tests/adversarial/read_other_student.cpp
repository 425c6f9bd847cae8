// adversarial 2.2: looks for another student's work beside its own folder
// @helpers
#include <filesystem>
// @body
    std::error_code e;
    int found = 0;
    for (const auto& d : std::filesystem::directory_iterator(std::filesystem::current_path().parent_path(), e))
        if (std::filesystem::exists(d.path() / "ch02_spheres.cpp", e)) ++found;
    t_near = t_far = 0;
    return found > 1;
