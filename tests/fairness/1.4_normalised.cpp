// fairness 1.4 fail: the direction normalised
// A unit direction points the right way, but t = 1 is no longer the image plane, which the
// contract (and chapter 16's thin lens) rely on.
// @body
    return Ray{eye, glm::normalize(uv.x * uvw.u + uv.y * uvw.v - d * uvw.w)};
