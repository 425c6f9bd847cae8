// fairness 4.3 fail: t strictly inside (min, max)
// The interval is closed (book §2.4): a hit exactly at min or max counts.
// @body
    const Vec3& n = polygon.normal();
    const Real denominator = glm::dot(ray.direction, n);
    if (denominator == 0) return false;
    const Real t = glm::dot(polygon.vertices()[0] - ray.origin, n) / denominator;
    if (t <= interval.min || t >= interval.max) return false;
    const Vec3 p = ray.at(t);
    const auto& axes = polygon.axes();
    if (!inside_polygon_2d(polygon.projected(), Vec2(p[axes[0]], p[axes[1]]))) return false;
    result = PolygonHit{t};
    return true;
