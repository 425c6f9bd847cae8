// fairness 2.1 pass: the discriminant with a fused multiply-add, b^2 - A C in one rounding
// @body
    const Vec3& d = ray.direction;
    const Vec3 f = ray.origin - center;
    const Real a = glm::dot(d, d);
    const Real b = glm::dot(d, f);
    const Real c = glm::dot(f, f) - radius * radius;
    const Real discriminant = std::fma(b, b, -(a * c));
    if (discriminant < 0) return false;
    const Real root = std::sqrt(discriminant);
    t_near = -(b + root) / a;
    t_far = (root - b) / a;
    return true;
