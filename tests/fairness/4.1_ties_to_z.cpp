// fairness 4.1 pass: ties go to the later axis (>=), where the reference keeps the earlier
// A normal with two equal largest components projects with the same area onto either plane:
// the choice between them is free.
// @body
    const Real x = std::abs(n.x), y = std::abs(n.y), z = std::abs(n.z);
    if (z >= x && z >= y) return {0, 1};
    if (y >= x) return {0, 2};
    return {1, 2};
