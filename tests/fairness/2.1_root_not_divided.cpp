// fairness 2.1 fail: -b/A +- sqrt(discriminant), the square root not divided by A
// Right whenever A = 1, which every unit direction has.
// @body
    const Vec3& d = ray.direction;
    const Vec3 f = ray.origin - center;
    const Real a = glm::dot(d, d);
    const Real b = glm::dot(d, f);
    const Real discriminant = b * b - a * (glm::dot(f, f) - radius * radius);
    if (discriminant < 0) return false;
    const Real root = std::sqrt(discriminant);
    t_near = -b / a - root;
    t_far = -b / a + root;
    return true;
