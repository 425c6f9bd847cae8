// fairness 9.3 fail: the corners carried as vectors, without the translation
// @body
    Box result;
    for (int corner = 0; corner < 8; ++corner)
        result.expand(to_world.vector(Vec3(corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                                           corner & 4 ? box.max.z : box.min.z)));
    return result;
