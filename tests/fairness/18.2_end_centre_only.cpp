// fairness 18.2 fail: the box of the sphere at time 0 grown to the end point of its centre,
// forgetting the sphere's radius around that end: at time 1 the sphere sticks out of the box
// by its radius, and a structure built from it misses the sphere there
// @body
    const Vec3 r(sphere.radius);
    Box box{sphere.center - r, sphere.center + r};
    box.expand(sphere.center + sphere.motion);
    return box;
