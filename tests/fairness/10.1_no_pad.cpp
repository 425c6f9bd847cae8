// fairness 10.1 fail: the slab test without the padding of the far end: a ray through a box's
// edge or corner, where entry and exit are equal, can come out with the entry an ulp later and
// lose the box (§10.1 "Rounding must never lose a hit")
// @body
    Real t0 = interval.min, t1 = interval.max;
    for (int axis = 0; axis < 3; ++axis) {
        const Real a = Real(1) / ray.direction[axis];
        Real near = (box.min[axis] - ray.origin[axis]) * a;
        Real far = (box.max[axis] - ray.origin[axis]) * a;
        if (a < 0) std::swap(near, far);
        if (near > t0) t0 = near;
        if (far < t1) t1 = far;
    }
    return t0 <= t1;
