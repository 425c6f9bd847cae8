// fairness 2.2 pass: h from the cross product, |f x d| / |d|, and the roots ordered by the sign of q
// The distance from the centre to the line without the foot point; q > 0 exactly when b < 0,
// and then q / a is the far root.
// @body
    const Vec3& d = ray.direction;
    const Vec3 f = ray.origin - center;
    const Real a = glm::dot(d, d);
    const Real b = glm::dot(f, d);
    const Real h = glm::length(glm::cross(f, d)) / std::sqrt(a);
    const Real discriminant = a * (radius - h) * (radius + h);
    if (discriminant < 0) return false;
    const Real q = -(b + std::copysign(std::sqrt(discriminant), b));
    if (q == 0) {
        t_near = t_far = 0;
        return true;
    }
    const Real c = glm::dot(f, f) - radius * radius;
    if (q > 0) {
        t_near = c / q;
        t_far = q / a;
    } else {
        t_near = q / a;
        t_far = c / q;
    }
    return true;
