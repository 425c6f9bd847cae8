// fairness 9.2 fail: (M^-1)^T n left at whatever length the scale gives it
// @body
    return glm::transpose(to_object.m) * n;
