// fairness 10.1 fail: std::max(near, t0) and std::min(far, t1) pass a NaN on (a ray lying in a
// face's plane, 0 * inf), so the box is rejected when that axis is the last one to update
// (§10.1 "A ray in the plane of a face")
// @body
    Real t0 = interval.min, t1 = interval.max;
    for (int axis = 0; axis < 3; ++axis) {
        const Real a = Real(1) / ray.direction[axis];
        Real near = (box.min[axis] - ray.origin[axis]) * a;
        Real far = (box.max[axis] - ray.origin[axis]) * a;
        if (a < 0) std::swap(near, far);
        t0 = std::max(near, t0);
        t1 = std::min(far, t1);
    }
    return t0 <= t1 + std::abs(t1) * (4 * std::numeric_limits<Real>::epsilon());
