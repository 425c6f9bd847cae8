// fairness 5.3 fail: no test of which side the light is on
// max(0, n . h) alone still lights a surface whose light is behind it whenever the eye is
// far enough in front for h to tip over to its side.
// @body
    const Vec3 h = glm::normalize(l + v);
    const float cosine = float(glm::dot(n, h));
    return cosine > 0 ? light * specular * std::pow(cosine, exponent) : Color(0);
