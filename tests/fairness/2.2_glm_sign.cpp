// fairness 2.2 fail: the stable roots with glm::sign(b), which is 0 for b = 0
// Right everywhere else, but for a ray whose closest approach to the centre is its origin
// (b = 0) q is 0, and the roots come out as a false double root at 0 (book §2.3: sign(0) = +1).
// @body
    const Vec3& d = ray.direction;
    const Vec3 f = ray.origin - center;
    const Real a = glm::dot(d, d);
    const Real b = glm::dot(f, d);
    const Vec3 foot = f - (b / a) * d;
    const Real h = std::sqrt(glm::dot(foot, foot));
    const Real discriminant = a * (radius - h) * (radius + h);
    if (discriminant < 0) return false;
    const Real q = -(b + glm::sign(b) * std::sqrt(discriminant));
    const Real c = glm::dot(f, f) - radius * radius;
    if (q == 0) {
        t_near = t_far = 0;
        return true;
    }
    const Real t_a = q / a, t_b = c / q;
    t_near = std::min(t_a, t_b);
    t_far = std::max(t_a, t_b);
    return true;
