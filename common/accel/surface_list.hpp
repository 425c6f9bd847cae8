#pragma once
// The scene's surfaces, in one flat list (course §9.4): the brute-force search every
// acceleration structure of chapters 10-12 must agree with, hit for hit, except at exactly
// equal t, where this list keeps the later surface and the structures (ranking with
// closer()) the earlier one (book §5.3).
#include "accel/surface.hpp"

#include <string>
#include <vector>

namespace rt {

class SurfaceList {
public:
    // Adds a surface and returns its id. An empty name becomes "KIND N" (e.g. "sphere 3").
    SurfaceId add(Shape shape, MaterialId material = 0, std::string name = "");

    // Exercise 5.1: the closest hit over all surfaces in the interval, as the whole record of
    // the surface that made it; false and rec untouched if there is none. Of surfaces hit at
    // exactly the same t, the later in the list (what shrinking the interval's max to each
    // hit's t gives, the interval being closed); the search order is free.
    bool hit(const Ray& ray, Interval interval, HitRecord& rec) const;
    // Any hit in the interval, stopping at the first: the query of shadow rays.
    bool occluded(const Ray& ray, Interval interval) const;
    Box bounding_box() const { return box_; }
    // Whether any surface moves (chapter 18): rays then need a time, and otherwise do not.
    bool moves() const { return moves_; }

    std::size_t size() const { return surfaces_.size(); }
    bool empty() const { return surfaces_.empty(); }
    const Surface& operator[](SurfaceId id) const { return surfaces_[id]; }
    const std::vector<Surface>& surfaces() const { return surfaces_; }
    // Names live apart from the surfaces: the hot loop never touches them.
    const std::string& name(SurfaceId id) const { return names_[id]; }

private:
    std::vector<Surface> surfaces_;
    std::vector<std::string> names_;
    Box box_;
    bool moves_ = false;
};

}  // namespace rt
