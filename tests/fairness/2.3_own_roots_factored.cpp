// fairness 2.3 pass: the roots worked out here, stably, with C factored as (|f| - R)(|f| + R)
// 2.3 need not call 2.2: any roots within the contract's rounding pick the same hit.
// @body
    const Vec3& d = ray.direction;
    const Vec3 f = ray.origin - sphere.center;
    const Real a = glm::dot(d, d);
    const Real b = glm::dot(f, d);
    const Vec3 foot = f - (b / a) * d;
    const Real h = glm::length(foot);
    const Real discriminant = a * (sphere.radius - h) * (sphere.radius + h);
    if (discriminant < 0) return false;
    const Real q = -(b + std::copysign(std::sqrt(discriminant), b));
    const Real distance = glm::length(f);
    const Real c = (distance - sphere.radius) * (distance + sphere.radius);
    const Real t0 = q == 0 ? 0 : std::min(q / a, c / q), t1 = q == 0 ? 0 : std::max(q / a, c / q);
    for (const Real t : {t0, t1})
        if (interval.contains(t)) {
            result = SphereHit{t};
            return true;
        }
    return false;
