// fairness 1.1 fail: u = up x w left unnormalised
// Unit for a level view, where up is perpendicular to w; shorter for any other, which
// stretches the image sideways.
// @body
    const Vec3 w = -glm::normalize(view_direction);
    const Vec3 u = glm::cross(up, w);
    const Vec3 v = glm::cross(w, glm::normalize(u));
    return Basis{u, v, w};
