#pragma once
#include "common/box.hpp"
#include "common/hit_record.hpp"
#include "common/ray.hpp"

#include <memory>
#include <string>
#include <utility>

namespace rt {

struct Material;

// Anything a ray can hit (§9.4.1): primitives, lists of surfaces, and later the
// acceleration structures, which are surfaces too.
class Surface {
public:
    explicit Surface(std::string name) : name_(std::move(name)) {}
    virtual ~Surface() = default;

    // True if the ray hits at some t in [t0, t1]; then rec describes the closest such hit.
    virtual bool hit(const Ray& ray, Real t0, Real t1, HitRecord& rec) const = 0;
    virtual Box bounding_box() const = 0;

    const std::string& name() const { return name_; }

    // What the surface is made of; null for the chapters that shade geometry only.
    const Material* material() const { return material_.get(); }
    void set_material(std::shared_ptr<const Material> m) { material_ = std::move(m); }

private:
    std::string name_;
    std::shared_ptr<const Material> material_;
};

}  // namespace rt
