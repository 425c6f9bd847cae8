// fairness 4.3 fail: only rays that meet the polygon's front (d . n < 0)
// Back-face culling: right for closed solids seen from outside, but a polygon is one-sided
// nowhere in the contract, and a floor seen from below, or a mirror's back, disappears.
// @body
    const Vec3& n = polygon.normal();
    const Real denominator = glm::dot(ray.direction, n);
    if (denominator >= 0) return false;
    const Real t = glm::dot(polygon.vertices()[0] - ray.origin, n) / denominator;
    if (!interval.contains(t)) return false;
    const Vec3 p = ray.at(t);
    const auto& axes = polygon.axes();
    if (!inside_polygon_2d(polygon.projected(), Vec2(p[axes[0]], p[axes[1]]))) return false;
    result = PolygonHit{t};
    return true;
