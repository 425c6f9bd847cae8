// fairness 9.3 fail: the corner loop stops one short (corner < 7): the corner (max, max, max) is never transformed
// A turn about an axis shares each extreme between two corners, so the box comes out right
// there; a turn whose extremes each belong to one corner loses the last one's.
// @body
    Box result;
    for (int corner = 0; corner < 7; ++corner)
        result.expand(to_world.point(Vec3(corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                                          corner & 4 ? box.max.z : box.min.z)));
    return result;
