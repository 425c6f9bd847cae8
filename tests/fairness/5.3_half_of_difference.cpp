// fairness 5.3 fail: h from l - v, as if v pointed from the eye
// The contract's v points towards the eye, like l towards the light.
// @body
    if (glm::dot(n, l) <= 0) return Color(0);
    const float cosine = float(glm::dot(n, glm::normalize(l - v)));
    return cosine > 0 ? light * specular * std::pow(cosine, exponent) : Color(0);
