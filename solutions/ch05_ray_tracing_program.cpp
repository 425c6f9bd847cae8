// Chapter 05 exercises: the ray tracing program (book §5, course §9.4-9.4.1). Declared in
// common/accel/surface_list.hpp and common/shading/shading.hpp.
#include "accel/surface_list.hpp"
#include "core/exercise.hpp"
#include "shading/shading.hpp"

#include <cmath>

namespace rt {

// @book closest
bool SurfaceList::hit(const Ray& ray, Interval interval, HitRecord& rec) const {
    // @exercise 5.1 | SurfaceList::hit | book §5.2
    // Each hit shrinks the interval, so every later surface can only report something
    // closer, and rec ends up describing the closest hit. A surface that misses leaves rec
    // alone; one that hits replaces all of it.
    bool found = false;
    for (const Surface& surface : surfaces_)
        if (surface.hit(ray, interval, rec)) {
            found = true;
            interval.max = rec.t;
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

Color blinn_phong_highlight(const Color& specular, float exponent, const Color& light, const Vec3& n, const Vec3& l,
                            const Vec3& v) {
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
