#pragma once
// A list of surfaces is itself a surface (§9.4): the renderer holds one Surface for the
// whole model, and later the acceleration structures take its place unchanged.
#include "common/surface.hpp"

#include <memory>
#include <vector>

namespace rt {

class SurfaceList : public Surface {
public:
    explicit SurfaceList(std::string name = "world") : Surface(std::move(name)) {}

    void add(std::shared_ptr<const Surface> s);

    // Exercise 5.1: the closest hit over all members in [t0, t1].
    bool hit(const Ray& ray, Real t0, Real t1, HitRecord& rec) const override;
    Box bounding_box() const override { return box_; }

    const std::vector<std::shared_ptr<const Surface>>& surfaces() const { return surfaces_; }

private:
    std::vector<std::shared_ptr<const Surface>> surfaces_;
    Box box_;
};

}  // namespace rt
