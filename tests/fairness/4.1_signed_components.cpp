// fairness 4.1 fail: the components compared with their signs
// Right for normals with positive components; a normal along -y is taken for one along x.
// @body
    if (n.z > n.x && n.z > n.y) return {0, 1};
    if (n.y > n.x) return {0, 2};
    return {1, 2};
