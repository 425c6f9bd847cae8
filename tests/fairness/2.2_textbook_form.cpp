// fairness 2.2 fail: the textbook's quadratic formula in place of the stable one
// It agrees near the sphere, but -b + sqrt(b^2 - ...) cancels for a sphere far away (book §2.3),
// which is exactly what 2.2 is for.
// @body
    const Vec3 f = ray.origin - center;
    const Real a = glm::dot(ray.direction, ray.direction);
    const Real b = glm::dot(f, ray.direction);
    const Real discriminant = b * b - a * (glm::dot(f, f) - radius * radius);
    if (discriminant < 0) return false;
    t_near = (-b - std::sqrt(discriminant)) / a;
    t_far = (-b + std::sqrt(discriminant)) / a;
    return true;
