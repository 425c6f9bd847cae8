// fairness 2.1 fail: A taken as 1, as if the direction were unit length
// Book §2.1's most common bug: right for every unit direction, off by |d|^2 for the others.
// @body
    const Vec3 f = ray.origin - center;
    const Real b = glm::dot(ray.direction, f);
    const Real discriminant = b * b - (glm::dot(f, f) - radius * radius);
    if (discriminant < 0) return false;
    t_near = -b - std::sqrt(discriminant);
    t_far = -b + std::sqrt(discriminant);
    return true;
