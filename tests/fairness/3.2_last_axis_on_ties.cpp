// fairness 3.2 pass: the largest component of d found with >=, so ties go to the later axis
// Any axis where d is largest keeps the shear bounded; the choice among equals is free.
// @body
    const Vec3& d = ray.direction;
    const Vec3 ad = glm::abs(d);
    int kz = 0;
    for (int axis = 1; axis < 3; ++axis)
        if (ad[axis] >= ad[kz]) kz = axis;
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (d[kz] < 0) std::swap(kx, ky);
    const Real Sx = d[kx] / d[kz], Sy = d[ky] / d[kz], Sz = Real(1) / d[kz];
    const Vec3 a = A - ray.origin, b = B - ray.origin, c = C - ray.origin;
    const Real ax = a[kx] - Sx * a[kz], ay = a[ky] - Sy * a[kz];
    const Real bx = b[kx] - Sx * b[kz], by = b[ky] - Sy * b[kz];
    const Real cx = c[kx] - Sx * c[kz], cy = c[ky] - Sy * c[kz];
    const Real U = cx * by - cy * bx, V = ax * cy - ay * cx, W = bx * ay - by * ax;
    if ((U < 0 || V < 0 || W < 0) && (U > 0 || V > 0 || W > 0)) return false;
    const Real det = U + V + W;
    if (det == 0) return false;
    const Real T = U * (Sz * a[kz]) + V * (Sz * b[kz]) + W * (Sz * c[kz]);
    const Real t0 = interval.min, t1 = interval.max;
    if (det > 0 ? (T < t0 * det || T > t1 * det) : (T > t0 * det || T < t1 * det)) return false;
    const Real inv = Real(1) / det;
    result = TriangleHit{T * inv, V * inv, W * inv};
    return true;
