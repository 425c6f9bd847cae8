// fairness 7.1 pass: the projection onto n divided by n . n, right for a normal of any length
// For the unit normal of the contract n . n is 1 to within rounding.
// @body
    return d - (2 * glm::dot(d, n) / glm::dot(n, n)) * n;
