// fairness 2.1 pass: the quadratic with the whole B = 2 d.f: t = (-B -+ sqrt(B^2 - 4AC)) / 2A
// The course's formula before halving B (book §2.1): every factor of 2 and 4 is exact.
// @body
    const Vec3 f = ray.origin - center;
    const Real A = glm::dot(ray.direction, ray.direction);
    const Real B = 2 * glm::dot(ray.direction, f);
    const Real C = glm::dot(f, f) - radius * radius;
    const Real discriminant = B * B - 4 * A * C;
    if (discriminant < 0) return false;
    const Real root = std::sqrt(discriminant);
    t_near = (-B - root) / (2 * A);
    t_far = (-B + root) / (2 * A);
    return true;
