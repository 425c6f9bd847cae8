// fairness 3.2 pass: x and y never swapped when d_z < 0
// The swap keeps the edge functions' signs for back-face culling; a test that accepts all
// three >= 0 or all three <= 0 gets the same answers without it (det changes sign with them).
// Every rounding is the same as the reference's, up to the sign.
// @body
    const Vec3& d = ray.direction;
    const Vec3 ad = glm::abs(d);
    const int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    const int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    const Real Sx = d[kx] / d[kz], Sy = d[ky] / d[kz], Sz = Real(1) / d[kz];
    const Vec3 a = A - ray.origin, b = B - ray.origin, c = C - ray.origin;
    const Real ax = a[kx] - Sx * a[kz], ay = a[ky] - Sy * a[kz];
    const Real bx = b[kx] - Sx * b[kz], by = b[ky] - Sy * b[kz];
    const Real cx = c[kx] - Sx * c[kz], cy = c[ky] - Sy * c[kz];
    const Real U = cx * by - cy * bx, V = ax * cy - ay * cx, W = bx * ay - by * ax;
    if ((U < 0 || V < 0 || W < 0) && (U > 0 || V > 0 || W > 0)) return false;
    const Real det = U + V + W;
    if (det == 0) return false;
    const Real t = (U * (Sz * a[kz]) + V * (Sz * b[kz]) + W * (Sz * c[kz])) / det;
    if (!interval.contains(t)) return false;
    result = TriangleHit{t, V / det, W / det};
    return true;
