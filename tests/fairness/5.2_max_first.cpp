// fairness 5.2 pass: max(0, n . l) first, then the product, in the order the course writes it
// @helpers
#include <algorithm>
// @body
    const float cosine = std::max(0.0f, float(glm::dot(n, l)));
    return diffuse * light * cosine;
