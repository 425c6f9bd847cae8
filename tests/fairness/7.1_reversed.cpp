// fairness 7.1 fail: r = 2 (d . n) n - d, the formula for a vector pointing away from the surface
// That is the mirror of l (towards the light) in Phong's model; d points towards the surface.
// @body
    return 2 * glm::dot(d, n) * n - d;
