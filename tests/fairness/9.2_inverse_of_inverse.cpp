// fairness 9.2 fail: the inverse transpose of the matrix given, which is already M^-1: (M^-1)^-T = M^T
// The course's rule is for M; here the argument is the inverse already.
// @body
    return unit_vector(glm::transpose(glm::inverse(to_object.m)) * n);
