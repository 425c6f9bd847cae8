// fairness 3.1 pass: Cramer's rule in vectors: the determinants as triple products
// M = (a - b) . ((a - c) x d), and each numerator the same with a - e in its column: the
// course's minors, grouped as cross products (Moller and Trumbore's form).
// @body
    const Vec3 ab = A - B, ac = A - C, ae = A - ray.origin;
    const Vec3& d = ray.direction;
    const Real M = glm::dot(ab, glm::cross(ac, d));
    if (M == 0) return false;
    const Real t = glm::dot(ab, glm::cross(ac, ae)) / M;
    if (!interval.contains(t)) return false;
    const Real gamma = glm::dot(ab, glm::cross(ae, d)) / M;
    if (gamma < 0 || gamma > 1) return false;
    const Real beta = glm::dot(ae, glm::cross(ac, d)) / M;
    if (beta < 0 || beta > 1 - gamma) return false;
    result = TriangleHit{t, beta, gamma};
    return true;
