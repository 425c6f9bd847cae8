// fairness 9.1 fail: the direction as the difference of two transformed points, M^-1 (e + d) - M^-1 e
// The same vector in exact arithmetic, but both points carry the translation: an instance
// 10^6 from the origin leaves the direction only the digits its size allows.
// @body
    const Vec3 origin = to_object.point(ray.origin);
    return Ray{origin, to_object.point(ray.origin + ray.direction) - origin, ray.time};
