// fairness 2.2 pass: both cures, with C factored as (|f| - R)(|f| + R)
// On the grazing ray of the old test, (|f| - R)(|f| + R) with |f| = sqrt(26) is one ulp below
// 25, and C/q gives 4.9999999999999991 for 5 (issue 42): a rounding the contract allows.
// @body
    const Vec3& d = ray.direction;
    const Vec3 f = ray.origin - center;
    const Real a = glm::dot(d, d);
    const Real b = glm::dot(f, d);
    const Vec3 foot = f - (b / a) * d;
    const Real h = glm::length(foot);
    const Real discriminant = a * (radius - h) * (radius + h);
    if (discriminant < 0) return false;
    const Real q = -(b + std::copysign(std::sqrt(discriminant), b));
    const Real distance = glm::length(f);
    const Real c = (distance - radius) * (distance + radius);
    if (q == 0) {
        t_near = t_far = 0;
        return true;
    }
    t_near = std::min(q / a, c / q);
    t_far = std::max(q / a, c / q);
    return true;
