// fairness 5.2 fail: the light's colour left out
// Right for white lights of intensity 1, which most scenes have.
// @body
    const float cosine = float(glm::dot(n, l));
    return cosine > 0 ? diffuse * cosine : Color(0);
