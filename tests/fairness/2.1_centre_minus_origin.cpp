// fairness 2.1 fail: f = c - e instead of e - c
// f.f is the same either way, so C is right, but b changes sign and both roots with it: the
// sphere in front is reported behind the eye.
// @body
    const Vec3& d = ray.direction;
    const Vec3 f = center - ray.origin;
    const Real a = glm::dot(d, d);
    const Real b = glm::dot(d, f);
    const Real discriminant = b * b - a * (glm::dot(f, f) - radius * radius);
    if (discriminant < 0) return false;
    const Real root = std::sqrt(discriminant);
    t_near = (-b - root) / a;
    t_far = (-b + root) / a;
    return true;
