// fairness 4.1 pass: the components compared by their squares, and the kept axes by arithmetic
// n_i^2 orders like |n_i|; the two kept axes, in increasing order, are those after the
// dropped one, turned round when it is y.
// @body
    const Real x = n.x * n.x, y = n.y * n.y, z = n.z * n.z;
    const int drop = z > x && z > y ? 2 : y > x ? 1 : 0;
    const int first = drop == 0 ? 1 : 0, second = drop == 2 ? 1 : 2;
    return {first, second};
