// fairness 9.3 fail: the corners counted from 1: the corner (min, min, min) is never transformed
// @body
    Box result;
    for (int corner = 1; corner < 8; ++corner)
        result.expand(to_world.point(Vec3(corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                                          corner & 4 ? box.max.z : box.min.z)));
    return result;
