// fairness 5.3 pass: n . h as n . (l + v) / |l + v|, h never normalised
// @body
    if (glm::dot(n, l) <= 0) return Color(0);
    const Vec3 sum = l + v;
    const float cosine = float(glm::dot(n, sum) / glm::length(sum));
    return cosine > 0 ? light * specular * std::pow(cosine, exponent) : Color(0);
