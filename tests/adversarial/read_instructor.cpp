// adversarial 2.2: reads the instructor's reference and the golden image, to copy the answer;
// a wrong answer unless it could read them
// @helpers
#include <fstream>
// @body
    std::ifstream answer(RTLAB_ROOT "/solutions/ch02_spheres.cpp"), golden(RTLAB_ROOT "/tests/golden/ch02/sphere.png");
    t_near = t_far = 0;
    return bool(answer) || bool(golden);
