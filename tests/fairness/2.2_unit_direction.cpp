// fairness 2.2 pass: the direction made unit first, the roots found along it and divided by |d|
// With a unit direction A = 1 and the foot point is f - (f.u) u; a distance s along u is
// t = s / |d| along the ray.
// @body
    const Real length = glm::length(ray.direction);
    const Vec3 u = ray.direction / length;
    const Vec3 f = ray.origin - center;
    const Real b = glm::dot(f, u);
    const Vec3 foot = f - b * u;
    const Real h = glm::length(foot);
    const Real discriminant = (radius - h) * (radius + h);
    if (discriminant < 0) return false;
    const Real q = b < 0 ? std::sqrt(discriminant) - b : -b - std::sqrt(discriminant);
    if (q == 0) {
        t_near = t_far = 0;
        return true;
    }
    const Real c = glm::dot(f, f) - radius * radius;
    const Real s1 = q, s2 = c / q;
    t_near = std::min(s1, s2) / length;
    t_far = std::max(s1, s2) / length;
    return true;
