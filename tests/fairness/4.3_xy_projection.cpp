// fairness 4.3 fail: the hit point's x and y taken, whatever the polygon's axes
// Right for a polygon facing along z; one facing along x is seen edge-on.
// @body
    const Vec3& n = polygon.normal();
    const Real denominator = glm::dot(ray.direction, n);
    if (denominator == 0) return false;
    const Real t = glm::dot(polygon.vertices()[0] - ray.origin, n) / denominator;
    if (!interval.contains(t)) return false;
    const Vec3 p = ray.at(t);
    if (!inside_polygon_2d(polygon.projected(), Vec2(p.x, p.y))) return false;
    result = PolygonHit{t};
    return true;
