// fairness 9.1 pass: the translation added before the matrix's product, t + M^-1 e
// @body
    return Ray{to_object.t + to_object.m * ray.origin, to_object.m * ray.direction, ray.time};
