// fairness 7.1 pass: d split into its tangent and normal parts; the normal part turned round
// r = (d - (d.n) n) - (d.n) n: the tangent part kept, the normal part reversed.
// @body
    const Vec3 normal_part = glm::dot(d, n) * n;
    const Vec3 tangent_part = d - normal_part;
    return tangent_part - normal_part;
