// fairness 4.1 fail: the course's pseudo-code as printed, |z| compared with |x| twice
// The book's erratum (§4.2): it keeps x and y for n = (0.1, 0.9, 0.5), a polygon seen almost
// edge-on in that projection.
// @body
    const Real x = std::abs(n.x), y = std::abs(n.y), z = std::abs(n.z);
    if (z > x && z > x) return {0, 1};
    if (y > x) return {0, 2};
    return {1, 2};
