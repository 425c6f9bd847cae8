// fairness 3.2 pass: t = T / det first, then interval.contains(t); the barycentrics by division
// The reference compares T with t0 det and t1 det to save a division on a miss; dividing first
// rounds t once more before the test, which the contract allows.
// @body
    const Vec3& d = ray.direction;
    const Vec3 ad = glm::abs(d);
    const int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (d[kz] < 0) std::swap(kx, ky);
    const Real Sx = d[kx] / d[kz], Sy = d[ky] / d[kz], Sz = Real(1) / d[kz];
    const Vec3 a = A - ray.origin, b = B - ray.origin, c = C - ray.origin;
    const Real ax = a[kx] - Sx * a[kz], ay = a[ky] - Sy * a[kz];
    const Real bx = b[kx] - Sx * b[kz], by = b[ky] - Sy * b[kz];
    const Real cx = c[kx] - Sx * c[kz], cy = c[ky] - Sy * c[kz];
    const Real U = cx * by - cy * bx, V = ax * cy - ay * cx, W = bx * ay - by * ax;
    const bool negative = U < 0 || V < 0 || W < 0, positive = U > 0 || V > 0 || W > 0;
    if (negative && positive) return false;
    const Real det = U + V + W;
    if (det == 0) return false;
    const Real t = (U * (Sz * a[kz]) + V * (Sz * b[kz]) + W * (Sz * c[kz])) / det;
    if (!interval.contains(t)) return false;
    result = TriangleHit{t, V / det, W / det};
    return true;
