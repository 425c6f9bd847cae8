#include "common/surface_list.hpp"

namespace rt {

void SurfaceList::add(std::shared_ptr<const Surface> s) {
    box_.expand(s->bounding_box());
    surfaces_.push_back(std::move(s));
}

}  // namespace rt
