// fairness 10.1 fail: near and far ordered by comparing them, not by the sign of 1/d: when one
// is NaN (a ray lying in a face's plane) the comparison is false, and with a -0 component the
// planes stay the wrong way round (§10.1, core/box.hpp)
// @body
    Real t0 = interval.min, t1 = interval.max;
    for (int axis = 0; axis < 3; ++axis) {
        const Real a = Real(1) / ray.direction[axis];
        Real near = (box.min[axis] - ray.origin[axis]) * a;
        Real far = (box.max[axis] - ray.origin[axis]) * a;
        if (near > far) std::swap(near, far);
        if (near > t0) t0 = near;
        if (far < t1) t1 = far;
    }
    return t0 <= t1 + std::abs(t1) * (4 * std::numeric_limits<Real>::epsilon());
