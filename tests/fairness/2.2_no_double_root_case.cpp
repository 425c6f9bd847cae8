// fairness 2.2 fail: no case for q = 0
// q is 0 only for a line tangent to the sphere at the ray's own origin (book §2.3): C/q is then
// 0/0, and with C/q taken first, std::min and std::max hand the NaN on as both roots. (With
// q/A first they would return q/A both times, 0, by the luck of how they compare a NaN.)
// @body
    const Vec3& d = ray.direction;
    const Vec3 f = ray.origin - center;
    const Real a = glm::dot(d, d);
    const Real b = glm::dot(f, d);
    const Vec3 foot = f - (b / a) * d;
    const Real h = std::sqrt(glm::dot(foot, foot));
    const Real discriminant = a * (radius - h) * (radius + h);
    if (discriminant < 0) return false;
    const Real q = -(b + std::copysign(std::sqrt(discriminant), b));
    const Real c = glm::dot(f, f) - radius * radius;
    const Real t_a = c / q, t_b = q / a;
    t_near = std::min(t_a, t_b);
    t_far = std::max(t_a, t_b);
    return true;
