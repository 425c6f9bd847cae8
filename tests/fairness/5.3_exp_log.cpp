// fairness 5.3 pass: the power as exp(p log cos), and a light exactly in the surface's plane lit
// n . l = 0 is neither in front nor behind: the contract leaves it free, and this body
// computes the highlight there.
// @body
    if (glm::dot(n, l) < 0) return Color(0);
    const float cosine = float(glm::dot(n, glm::normalize(l + v)));
    if (cosine <= 0) return Color(0);
    return specular * light * std::exp(exponent * std::log(cosine));
