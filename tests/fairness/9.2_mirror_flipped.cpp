// fairness 9.2 fail: the normal turned round for a mirroring transform (det M < 0)
// A mirror reverses a mesh's winding, not its normals: (M^-1)^T n already points out of the
// transformed surface, whatever the determinant's sign.
// @body
    const Vec3 w = unit_vector(glm::transpose(to_object.m) * n);
    return glm::determinant(to_object.m) < 0 ? -w : w;
