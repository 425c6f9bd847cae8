// adversarial 2.2: writes outside its folder: into the lab's tree, the golden images, the
// grader, /tmp and the home folder
// @helpers
#include <cstdio>
// @body
    for (const char* path : {RTLAB_ROOT "/tests/golden/ch02/sphere.png", RTLAB_ROOT "/tools/grading/units.py",
                             RTLAB_ROOT "/solutions/ch02_spheres.cpp", "/tmp/rtlab-adversarial-was-here",
                             "/root/rtlab-adversarial-was-here", RTLAB_ROOT "/../rtlab-adversarial-was-here"})
        if (std::FILE* f = std::fopen(path, "a")) {
            std::fputs("pwned\n", f);
            std::fclose(f);
        }
    return false;
