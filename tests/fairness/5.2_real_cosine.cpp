// fairness 5.2 pass: the cosine clamped in Real and the colours multiplied channel by channel
// @body
    const Real cosine = glm::dot(l, n);
    if (!(cosine > 0)) return Color(0);
    Color out;
    for (int c = 0; c < 3; ++c) out[c] = diffuse[c] * (light[c] * float(cosine));
    return out;
