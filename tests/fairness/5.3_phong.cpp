// fairness 5.3 fail: Phong's (r . v)^p with the mirrored light r, not Blinn-Phong's (n . h)^p
// The same peak where v mirrors l, a narrower highlight everywhere else.
// @body
    if (glm::dot(n, l) <= 0) return Color(0);
    const Vec3 r = 2 * glm::dot(n, l) * n - l;
    const float cosine = float(glm::dot(r, v));
    return cosine > 0 ? light * specular * std::pow(cosine, exponent) : Color(0);
