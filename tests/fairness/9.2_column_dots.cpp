// fairness 9.2 pass: each coordinate as the dot product of a column of M^-1 with n, then divided by the length
// (M^-T n)_i is column i of M^-1 dotted with n.
// @body
    const Vec3 w(glm::dot(to_object.m[0], n), glm::dot(to_object.m[1], n), glm::dot(to_object.m[2], n));
    return w / glm::length(w);
