// fairness 2.2 fail: the stable roots (q and C/q) on the textbook discriminant b^2 - A C
// One cure of two (book §2.3): the roots no longer cancel, but for a small sphere far away
// b^2 and A C are both about A D^2 and their difference keeps only their rounding.
// @body
    const Vec3& d = ray.direction;
    const Vec3 f = ray.origin - center;
    const Real a = glm::dot(d, d);
    const Real b = glm::dot(f, d);
    const Real c = glm::dot(f, f) - radius * radius;
    const Real discriminant = b * b - a * c;
    if (discriminant < 0) return false;
    const Real q = -(b + std::copysign(std::sqrt(discriminant), b));
    if (q == 0) {
        t_near = t_far = 0;
        return true;
    }
    t_near = std::min(q / a, c / q);
    t_far = std::max(q / a, c / q);
    return true;
