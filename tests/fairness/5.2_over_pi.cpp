// fairness 5.2 fail: divided by pi, as a physically based Lambertian BRDF is
// Right in a renderer whose lights are radiometric; the course's model (and the contract)
// is c_r c_l max(0, n . l), with no pi.
// @body
    const float cosine = float(glm::dot(n, l));
    return cosine > 0 ? diffuse * light * cosine / 3.14159265f : Color(0);
