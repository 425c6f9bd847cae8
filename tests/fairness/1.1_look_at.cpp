// fairness 1.1 pass: glm::lookAt's construction: forward f, side s = f x up, then u = s x f, w = -f
// The rasteriser's frame, which is the course's with other names: s is u, and w looks back.
// @body
    const Vec3 f = glm::normalize(view_direction);
    const Vec3 s = glm::normalize(glm::cross(f, up));
    return Basis{s, glm::cross(s, f), -f};
