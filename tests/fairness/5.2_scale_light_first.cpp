// fairness 5.2 pass: the light scaled by the cosine, then tinted by the surface
// @body
    const float cosine = float(glm::dot(n, l));
    if (cosine <= 0) return Color(0);
    const Color arriving = light * cosine;
    return arriving * diffuse;
