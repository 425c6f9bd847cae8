// fairness 7.1 pass: glm::reflect, which computes I - N (N . I) 2, its own order of operations
// @body
    return glm::reflect(d, n);
