#pragma once
// A picture of a pixel's ray tree (book §7.5): the rays drawn over an orthographic
// projection of the scene, seen from above or from the side, whichever spreads the tree
// more. Hover over a ray for its details.
#include "render/ray_tree.hpp"
#include "render/scene.hpp"

#include <string>

namespace rt {

std::string ray_tree_svg(const Scene& scene, const RayTree& tree, const std::string& title, const Color& pixel);

}  // namespace rt
