// fairness 2.2 fail: t_near = C/q and t_far = q/A, without comparing them
// Right while b < 0 (the sphere ahead, the origin outside it), the case the book draws; for a
// ray whose origin is past the centre (b > 0) the two come out swapped.
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
    if (q == 0) {
        t_near = t_far = 0;
        return true;
    }
    t_near = (glm::dot(f, f) - radius * radius) / q;
    t_far = q / a;
    return true;
