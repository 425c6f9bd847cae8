// fairness 4.3 pass: the plane as n . x = D with D from the first vertex, t = (D - n . e) / (n . d)
// The course's plane equation, written with its offset instead of a vertex minus the origin.
// @body
    const Vec3& n = polygon.normal();
    const Real denominator = glm::dot(n, ray.direction);
    if (denominator == 0) return false;
    const Real D = glm::dot(n, polygon.vertices()[0]);
    const Real t = (D - glm::dot(n, ray.origin)) / denominator;
    if (t < interval.min || t > interval.max) return false;
    const std::array<int, 2>& axes = polygon.axes();
    const Vec2 p(ray.origin[axes[0]] + t * ray.direction[axes[0]], ray.origin[axes[1]] + t * ray.direction[axes[1]]);
    if (!inside_polygon_2d(polygon.projected(), p)) return false;
    result.t = t;
    return true;
