// fairness 9.1 pass: the ray copied and its origin and direction replaced, M^-1 written out by columns
// @body
    Ray out = ray;
    const Mat3& m = to_object.m;
    out.origin = m[0] * ray.origin.x + m[1] * ray.origin.y + m[2] * ray.origin.z + to_object.t;
    out.direction = m[0] * ray.direction.x + m[1] * ray.direction.y + m[2] * ray.direction.z;
    return out;
