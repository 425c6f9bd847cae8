// fairness 9.1 fail: the direction through the transpose of M^-1
// For a rotation that is M itself, not its inverse: the ray is turned the wrong way.
// @body
    return Ray{to_object.point(ray.origin), glm::transpose(to_object.m) * ray.direction, ray.time};
