// fairness 7.1 fail: the normal part taken away once, not twice
// The result lies in the surface's plane: the ray grazes it instead of bouncing.
// @body
    return d - glm::dot(d, n) * n;
