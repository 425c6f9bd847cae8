// fairness 9.2 pass: the transpose of M^-1 taken elementwise, and the normal made unit by its squared length
// @body
    Mat3 transposed;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) transposed[i][j] = to_object.m[j][i];
    const Vec3 w = transposed * n;
    return w * (Real(1) / std::sqrt(glm::dot(w, w)));
