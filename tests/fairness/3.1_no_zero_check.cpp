// fairness 3.1 fail: no test for M = 0
// A ray in the triangle's plane divides by zero; its infinite t passes [0, inf), the NaN
// barycentrics pass every comparison, and it "hits".
// @body
    const Vec3& d = ray.direction;
    const Real a = A.x - B.x, b = A.y - B.y, c = A.z - B.z;
    const Real dd = A.x - C.x, e = A.y - C.y, f = A.z - C.z;
    const Real g = d.x, h = d.y, i = d.z;
    const Real j = A.x - ray.origin.x, k = A.y - ray.origin.y, l = A.z - ray.origin.z;
    const Real ei_hf = e * i - h * f, gf_di = g * f - dd * i, dh_eg = dd * h - e * g;
    const Real ak_jb = a * k - j * b, jc_al = j * c - a * l, bl_kc = b * l - k * c;
    const Real M = a * ei_hf + b * gf_di + c * dh_eg;
    const Real t = -(f * ak_jb + e * jc_al + dd * bl_kc) / M;
    if (!interval.contains(t)) return false;
    const Real gamma = (i * ak_jb + h * jc_al + g * bl_kc) / M;
    if (gamma < 0 || gamma > 1) return false;
    const Real beta = (j * ei_hf + k * gf_di + l * dh_eg) / M;
    if (beta < 0 || beta > 1 - gamma) return false;
    result = TriangleHit{t, beta, gamma};
    return true;
