// fairness 5.2 fail: |n . l| in place of max(0, n . l)
// A light behind the surface lights it as much as one in front.
// @body
    return diffuse * light * std::abs(float(glm::dot(n, l)));
