// fairness 9.2 pass: n as a row vector times M^-1, n^T M^-1, which is (M^-T n)^T
// glm's v * m multiplies by the transpose: no transpose written, the same numbers.
// @body
    return glm::normalize(n * to_object.m);
