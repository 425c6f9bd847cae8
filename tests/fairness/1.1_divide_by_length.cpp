// fairness 1.1 pass: every normalisation as a division by the length, and v normalised too
// Slower and rounded differently from glm::normalize (which multiplies by an inverse square
// root), within the few epsilons the contract allows.
// @body
    const Vec3 w = -view_direction / glm::length(view_direction);
    Vec3 u = glm::cross(up, w);
    u /= glm::length(u);
    Vec3 v = glm::cross(w, u);
    v /= glm::length(v);
    return Basis{u, v, w};
