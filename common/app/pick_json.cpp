#include "app/pick_json.hpp"

namespace rt {

using nlohmann::json;

std::string dump(const json& j) {
    return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

namespace {

json to_json(const Vec3& v) {
    return json::array({v.x, v.y, v.z});
}

// Colours are float whatever Real is (and then the same type as Vec3): their own name.
json color_json(const Color& c) {
    return json::array({c.r, c.g, c.b});
}

json hit_json(const Scene& scene, const HitRecord& h) {
    json j{{"surface", h.surface < scene.surfaces.size() ? scene.surfaces.name(h.surface) : ""},
           {"t", h.t},
           {"point", to_json(h.p)},
           {"normal", to_json(h.normal)}};
    if (h.shading_normal != h.normal) j["shading_normal"] = to_json(h.shading_normal);
    if (h.primitive != kNone) j["triangle"] = h.primitive;
    if (h.part != kNone && h.surface < scene.surfaces.size())  // which operand of a CSG object
        j["operand"] = describe_part(scene.surfaces[h.surface].shape, h.part);
    return j;
}

// One ray of the tree and, nested, the rays it cast. JSON has no infinity: an interval
// that is open-ended ends in null.
json node_json(const Scene& scene, const RayTree& tree, const std::vector<std::vector<int>>& children, int i) {
    const RayNode& n = tree.nodes[std::size_t(i)];
    const auto end = [](Real v) { return std::isfinite(v) ? json(v) : json(nullptr); };
    json j{{"kind", kRayKindNames[n.kind]},
           {"depth", n.depth},
           {"origin", to_json(n.ray.origin)},
           {"direction", to_json(n.ray.direction)},
           {"interval", json::array({end(n.interval.min), end(n.interval.max)})}};
    if (n.kind == RayKind::shadow) {
        j["light"] = n.light;
        j["blocked"] = n.hit;
        if (n.hit && n.record.surface != kNone) j["blocker"] = hit_json(scene, n.record);
    } else {
        j["hit"] = n.hit ? hit_json(scene, n.record) : json(nullptr);
    }
    if (*n.weight_of) j["weight"] = {{"of", n.weight_of}, {"value", color_json(n.weight)}};
    j["radiance"] = color_json(n.radiance);
    if (*n.weight_of && n.kind != RayKind::shadow) j["contributes"] = color_json(n.weight * n.radiance);
    if (*n.note) j["note"] = n.note;
    json kids = json::array();
    for (int c : children[std::size_t(i)]) kids.push_back(node_json(scene, tree, children, c));
    if (!kids.empty()) j["children"] = kids;
    return j;
}

}  // namespace

json pick_json(const std::string& scene_name, const Scene& scene, int x, int y, const Pick& p) {
    json j{{"scene", scene_name},
           {"pixel", {x, y}},
           {"ray", {{"origin", to_json(p.ray.origin)}, {"direction", to_json(p.ray.direction)}}},
           {"hit", p.hit.has_value()}};
    if (p.hit) {
        const HitRecord& h = *p.hit;
        j.update(hit_json(scene, h));  // the same keys as the tree's hits, at the top level
        if (h.has_barycentrics) {
            j["beta"] = h.beta;
            j["gamma"] = h.gamma;
        }
    }
    j["color"] = color_json(p.color);
    if (!p.tree.nodes.empty()) {
        std::vector<std::vector<int>> children(p.tree.nodes.size());
        int root = -1;
        for (std::size_t i = 0; i < p.tree.nodes.size(); ++i) {
            const int parent = p.tree.nodes[i].parent;
            if (parent < 0) {
                if (root < 0) root = int(i);
            } else {
                children[std::size_t(parent)].push_back(int(i));
            }
        }
        j["tree"] = node_json(scene, p.tree, children, root);
    }
    return j;
}

}  // namespace rt
