// fairness 1.1 fail: v taken as up itself, normalised, not made perpendicular to w
// Right for a level view (the standard camera), but a camera looking down or up gets a v that
// leans into w: the frame is no longer orthogonal.
// @body
    const Vec3 w = -glm::normalize(view_direction);
    const Vec3 u = glm::normalize(glm::cross(up, w));
    return Basis{u, glm::normalize(up), w};
