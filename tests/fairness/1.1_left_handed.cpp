// fairness 1.1 fail: u = w x up, so u points left and u x v = -w
// Every vector has the right length and angle, and v is up, but the frame is left-handed:
// the image comes out mirrored.
// @body
    const Vec3 w = -glm::normalize(view_direction);
    const Vec3 u = glm::normalize(glm::cross(w, up));
    const Vec3 v = glm::cross(u, w);
    return Basis{u, v, w};
