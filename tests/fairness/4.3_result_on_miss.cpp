// fairness 4.3 fail: the plane's t written to result before the point is known to be inside
// A ray that meets the plane beside the polygon changes the caller's closest hit.
// @body
    const Vec3& n = polygon.normal();
    const Real denominator = glm::dot(ray.direction, n);
    if (denominator == 0) return false;
    const Real t = glm::dot(polygon.vertices()[0] - ray.origin, n) / denominator;
    if (!interval.contains(t)) return false;
    result = PolygonHit{t};
    const Vec3 p = ray.at(t);
    const auto& axes = polygon.axes();
    return inside_polygon_2d(polygon.projected(), Vec2(p[axes[0]], p[axes[1]]));
