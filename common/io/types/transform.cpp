// "transform": [{"scale": [sx, sy, sz]}, {"rotate": [x, y, z], "degrees": a}, {"translate": [x, y, z]}]
// Steps apply in the order listed, as in the course's ellipse (scale, rotate, translate).
// "scale" also takes one number for all three axes; a negative scale mirrors.
#include "io/scene_types.hpp"

namespace rt {

Affine read_transform(const Fields& f, const char* key) {
    Affine a;
    for (const Fields& step : f.objects(key)) {
        const int kinds = int(step.has("scale")) + int(step.has("rotate")) + int(step.has("translate"));
        if (kinds != 1) step.fail("", "each step has exactly one of 'scale', 'rotate' or 'translate'");
        if (step.has("degrees") != step.has("rotate")) step.fail("", "'rotate' and 'degrees' go together");
        Affine s;
        if (step.has("translate")) {
            s = Affine::translate(step.vec3("translate"));
        } else if (step.has("rotate")) {
            s = Affine::rotate(step.direction("rotate"), step.number("degrees", limits::angle));
        } else if (step.is_number("scale")) {
            const Real k = step.number("scale", limits::coordinate);
            s = Affine::scale(Vec3(k));
        } else {
            s = Affine::scale(step.vec3("scale"));
        }
        step.done();
        a = a.then(s);
    }
    try {
        (void)inverse(a, "");  // the message names the key already
    } catch (const std::invalid_argument& e) {
        f.fail(key, e.what());
    }
    return a;
}

}  // namespace rt
