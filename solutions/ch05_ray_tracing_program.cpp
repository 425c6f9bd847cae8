// Chapter 05 exercises: the ray tracing program (§9.4-9.4.1). Declared in
// common/surface_list.hpp and common/shading.hpp.
#include "common/exercise.hpp"
#include "common/shading.hpp"
#include "common/surface_list.hpp"

#include <cmath>

namespace rt {

// @book closest
bool SurfaceList::hit(const Ray& ray, Real t0, Real t1, HitRecord& rec) const {
    // @exercise 5.1 | SurfaceList::hit | book §5.2
    // Each hit shrinks the interval, so every later surface can only report something
    // closer, and rec ends up describing the closest hit.
    bool found = false;
    for (const auto& s : surfaces_)
        if (s->hit(ray, t0, t1, rec)) {
            found = true;
            t1 = rec.t;
        }
    return found;
    // @end
}
// @book-end

// @book shading
Color lambert(const Color& diffuse, const Color& light, const Vec3& n, const Vec3& l) {
    // @exercise 5.2 | lambert | book §5.4
    const float cosine = float(glm::dot(n, l));
    return cosine > 0 ? diffuse * light * cosine : Color(0);
    // @end
}

Color blinn_phong_highlight(const Color& specular, float exponent, const Color& light, const Vec3& n,
                            const Vec3& l, const Vec3& v) {
    // @exercise 5.3 | blinn_phong_highlight | book §5.4
    // No highlight from a light behind the surface, and max(0, .) before the power: an even
    // exponent would otherwise light up the side facing away from h.
    if (glm::dot(n, l) <= 0) return Color(0);
    const Vec3 h = glm::normalize(l + v);
    const float cosine = float(glm::dot(n, h));
    return cosine > 0 ? light * specular * std::pow(cosine, exponent) : Color(0);
    // @end
}
// @book-end

}  // namespace rt
