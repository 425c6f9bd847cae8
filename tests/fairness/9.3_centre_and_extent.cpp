// fairness 9.3 pass: Arvo's box: the centre transformed as a point, the half-extent by |M|
// Each row of the new half-extent is sum_j |m_ij| h_j: the farthest any corner reaches along
// that axis, without visiting the corners.
// @body
    const Vec3 centre = (box.min + box.max) * Real(0.5), half = (box.max - box.min) * Real(0.5);
    Mat3 absolute;
    for (int c = 0; c < 3; ++c) absolute[c] = glm::abs(to_world.m[c]);
    const Vec3 middle = to_world.point(centre), reach = absolute * half;
    Box result;
    result.min = middle - reach;
    result.max = middle + reach;
    return result;
