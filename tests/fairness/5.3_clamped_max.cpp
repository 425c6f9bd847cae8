// fairness 5.3 pass: max(0, n . h) before the power, and the light's side checked with float cosines
// @helpers
#include <algorithm>
// @body
    const float facing = float(glm::dot(n, l));
    if (!(facing > 0)) return Color(0);
    const float cosine = std::max(0.0f, float(glm::dot(n, glm::normalize(v + l))));
    return light * specular * std::pow(cosine, exponent);
