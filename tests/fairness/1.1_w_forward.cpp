// fairness 1.1 fail: w along the view direction, not against it
// The frame is still orthonormal and right-handed, but the eye then looks down +w and every
// perspective ray of 1.4 (-d w) points backwards (book §1.2).
// @body
    const Vec3 w = glm::normalize(view_direction);
    const Vec3 u = glm::normalize(glm::cross(up, w));
    const Vec3 v = glm::cross(w, u);
    return Basis{u, v, w};
