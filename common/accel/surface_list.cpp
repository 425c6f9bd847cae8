#include "accel/surface_list.hpp"

namespace rt {

SurfaceId SurfaceList::add(Shape shape, MaterialId material, std::string name) {
    const auto id = SurfaceId(surfaces_.size());
    if (name.empty()) name = std::string(shape_kind(shape)) + " " + std::to_string(id);
    surfaces_.push_back(Surface{std::move(shape), material, id});
    names_.push_back(std::move(name));
    box_.expand(surfaces_.back().bounding_box());
    moves_ = moves_ || rt::moves(surfaces_.back().shape);
    return id;
}

bool SurfaceList::occluded(const Ray& ray, Interval interval) const {
    for (const Surface& s : surfaces_)
        if (s.occluded(ray, interval)) return true;
    return false;
}

}  // namespace rt
