// fairness 2.2 pass: the stable roots with an if on the sign of b in place of std::copysign,
// b = 0 going with the positive branch (sign(0) = +1, book §2.3)
// @body
    const Vec3& d = ray.direction;
    const Vec3 f = ray.origin - center;
    const Real a = glm::dot(d, d);
    const Real b = glm::dot(f, d);
    const Vec3 foot = f - (b / a) * d;
    const Real h = std::sqrt(glm::dot(foot, foot));
    const Real discriminant = a * (radius - h) * (radius + h);
    if (discriminant < 0) return false;
    const Real root = std::sqrt(discriminant);
    const Real q = b < 0 ? root - b : -(b + root);
    if (q == 0) {
        t_near = t_far = 0;
        return true;
    }
    const Real c = glm::dot(f, f) - radius * radius;
    t_near = std::min(q / a, c / q);
    t_far = std::max(q / a, c / q);
    return true;
