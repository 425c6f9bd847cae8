// fairness 4.3 pass: the projection worked out again with the student's projection_axes and the vertices
// The polygon keeps its projection ready; building it here again costs time, not correctness.
// @body
    const Vec3& n = polygon.normal();
    const Real denominator = glm::dot(ray.direction, n);
    if (denominator == 0) return false;
    const Real t = glm::dot(polygon.vertices()[0] - ray.origin, n) / denominator;
    if (!interval.contains(t)) return false;
    const std::array<int, 2> axes = projection_axes(n);
    std::vector<Vec2> flat;
    for (const Vec3& v : polygon.vertices()) flat.emplace_back(v[axes[0]], v[axes[1]]);
    const Vec3 p = ray.at(t);
    if (!inside_polygon_2d(flat, Vec2(p[axes[0]], p[axes[1]]))) return false;
    result = PolygonHit{t};
    return true;
