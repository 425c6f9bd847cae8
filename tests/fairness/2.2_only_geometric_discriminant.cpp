// fairness 2.2 fail: the geometric discriminant A (R - h)(R + h) with the textbook roots (-b -+ root) / A
// One cure of two (book §2.3): the discriminant keeps its digits, but for a ray that starts
// close to the sphere the near root subtracts two almost equal numbers.
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
    t_near = (-b - root) / a;
    t_far = (-b + root) / a;
    return true;
