// fairness 7.1 fail: |d . n| used, as if n always faced the incoming ray
// Right for a normal on d's side (d . n < 0); with the other one it adds the normal part
// instead of reversing it: either side must work (the contract).
// @body
    return d + 2 * std::abs(glm::dot(d, n)) * n;
