// Chapter 15 exercises: soft shadows (book §15, course §9.11.2). Declared in
// common/core/sampler.hpp and common/shading/light.hpp.
#include "core/exercise.hpp"
#include "core/sampler.hpp"
#include "shading/light.hpp"

#include <utility>

namespace rt {

// @book shuffle
void fisher_yates(std::vector<std::uint32_t>& order, pcg32& random) {
    // @exercise 15.1 | fisher_yates | book §15.2
    // From the back: item i trades places with one of the items 0..i, each as likely, so
    // every one of the n! orders comes out with the same chance.
    for (std::size_t i = order.size(); i > 1; --i) {
        const std::size_t j = random(std::uint32_t(i));
        std::swap(order[i - 1], order[j]);
    }
    // @end
}
// @book-end

// @book light-point
Vec3 light_point(const Light& light, const Vec2& uv) {
    // @exercise 15.2 | light_point | book §15.1
    return light.position + uv.x * light.edge_a + uv.y * light.edge_b;
    // @end
}
// @book-end

}  // namespace rt
