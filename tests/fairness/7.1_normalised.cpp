// fairness 7.1 fail: the mirror direction normalised
// Points the right way, but the contract keeps d's length (a ray's t is measured in it).
// @body
    return glm::normalize(d - 2 * glm::dot(d, n) * n);
