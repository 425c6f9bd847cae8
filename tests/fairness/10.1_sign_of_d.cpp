// fairness 10.1 fail: the planes ordered by the sign of d, not of 1/d: "d < 0" is false for -0,
// whose reciprocal is -inf, so an axis-parallel ray with a -0 component gets an empty slab and
// passes through a box it lies inside (§10.1 "Minus zero")
// @body
    Real t0 = interval.min, t1 = interval.max;
    for (int axis = 0; axis < 3; ++axis) {
        const Real a = Real(1) / ray.direction[axis];
        Real near = (box.min[axis] - ray.origin[axis]) * a;
        Real far = (box.max[axis] - ray.origin[axis]) * a;
        if (ray.direction[axis] < 0) std::swap(near, far);
        if (near > t0) t0 = near;
        if (far < t1) t1 = far;
    }
    return t0 <= t1 + std::abs(t1) * (4 * std::numeric_limits<Real>::epsilon());
