// fairness 9.1 fail: the direction moved by the translation too, as a point is
// @body
    return Ray{to_object.point(ray.origin), to_object.point(ray.direction), ray.time};
