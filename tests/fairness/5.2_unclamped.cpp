// fairness 5.2 fail: n . l without the clamp
// A light behind the surface takes light away: negative colours that the other lights'
// terms then cancel.
// @body
    return diffuse * light * float(glm::dot(n, l));
