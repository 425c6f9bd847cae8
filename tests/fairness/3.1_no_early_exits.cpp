// fairness 3.1 pass: all three unknowns first, one reciprocal of M, then one test
// Slower on a scene (no early exits), the same answers to within rounding.
// @body
    const Vec3& d = ray.direction;
    const Real a = A.x - B.x, b = A.y - B.y, c = A.z - B.z;
    const Real dd = A.x - C.x, e = A.y - C.y, f = A.z - C.z;
    const Real g = d.x, h = d.y, i = d.z;
    const Real j = A.x - ray.origin.x, k = A.y - ray.origin.y, l = A.z - ray.origin.z;
    const Real M = a * (e * i - h * f) + b * (g * f - dd * i) + c * (dd * h - e * g);
    if (M == 0) return false;
    const Real inverse = 1 / M;
    const Real beta = (j * (e * i - h * f) + k * (g * f - dd * i) + l * (dd * h - e * g)) * inverse;
    const Real gamma = (i * (a * k - j * b) + h * (j * c - a * l) + g * (b * l - k * c)) * inverse;
    const Real t = -(f * (a * k - j * b) + e * (j * c - a * l) + dd * (b * l - k * c)) * inverse;
    if (!interval.contains(t) || beta < 0 || gamma < 0 || beta + gamma > 1) return false;
    result = TriangleHit{t, beta, gamma};
    return true;
