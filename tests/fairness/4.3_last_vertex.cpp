// fairness 4.3 pass: the plane through the last vertex, and the point projected with the polygon's own axes
// Every vertex lies on the plane; which one is used changes only the rounding of t.
// @body
    const Vec3& n = polygon.normal();
    const Real along = glm::dot(ray.direction, n);
    if (along == 0) return false;
    const Real t = glm::dot(polygon.vertices().back() - ray.origin, n) / along;
    if (!interval.contains(t)) return false;
    const Vec3 p = ray.at(t);
    const int u = polygon.axes()[0], v = polygon.axes()[1];
    if (!inside_polygon_2d(polygon.projected(), Vec2(p[u], p[v]))) return false;
    result = PolygonHit{t};
    return true;
