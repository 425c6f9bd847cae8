// fairness 5.3 fail: (n . h)^p without max(0, .)
// The light's side is checked, but an eye behind the surface with h tipped away gives a
// negative cosine, which an even exponent turns into a highlight.
// @body
    if (glm::dot(n, l) <= 0) return Color(0);
    const float cosine = float(glm::dot(n, glm::normalize(l + v)));
    return light * specular * std::pow(cosine, exponent);
