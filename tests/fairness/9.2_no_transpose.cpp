// fairness 9.2 fail: M^-1 n, as a direction is carried, not (M^-1)^T n
// Right for rotations (and for scales along the normal's own axis); a stretched sphere's
// normals no longer stand square to it.
// @body
    return unit_vector(to_object.m * n);
