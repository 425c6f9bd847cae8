#include "common/sphere.hpp"

#include <stdexcept>

namespace rt {

Sphere::Sphere(std::string name, const Vec3& center, Real radius)
    : Surface(std::move(name)), center_(center), radius_(radius) {
    if (!(radius > 0)) throw std::invalid_argument("sphere '" + this->name() + "': radius must be > 0");
}

Box Sphere::bounding_box() const {
    const Vec3 r(radius_);
    return Box{center_ - r, center_ + r};
}

}  // namespace rt
