// fairness 1.1 pass: v first, by Gram-Schmidt: up with its part along w taken away, then u = v x w
// The same right-handed frame built in the other order (book §1.2): w, then the v closest to
// up, then u completes it.
// @body
    const Vec3 w = -glm::normalize(view_direction);
    const Vec3 v = glm::normalize(up - glm::dot(up, w) * w);
    const Vec3 u = glm::cross(v, w);
    return Basis{u, v, w};
