// fairness 2.1 fail: a zero discriminant taken for a miss
// A line that touches the sphere has a double root (the header: t_near == t_far), not none.
// @body
    const Vec3& d = ray.direction;
    const Vec3 f = ray.origin - center;
    const Real a = glm::dot(d, d);
    const Real b = glm::dot(d, f);
    const Real discriminant = b * b - a * (glm::dot(f, f) - radius * radius);
    if (discriminant <= 0) return false;
    const Real root = std::sqrt(discriminant);
    t_near = (-b - root) / a;
    t_far = (-b + root) / a;
    return true;
