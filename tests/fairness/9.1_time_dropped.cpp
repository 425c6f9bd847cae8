// fairness 9.1 fail: the ray's time left behind: a moving sphere in an instance (chapter 18) stops
// @body
    return Ray{to_object.point(ray.origin), to_object.vector(ray.direction)};
