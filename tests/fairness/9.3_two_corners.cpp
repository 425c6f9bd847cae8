// fairness 9.3 fail: only the corners min and max transformed
// Right for scales and translations; a turned box reaches past both.
// @body
    Box result;
    result.expand(to_world.point(box.min));
    result.expand(to_world.point(box.max));
    return result;
