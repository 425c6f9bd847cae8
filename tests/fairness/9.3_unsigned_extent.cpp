// fairness 9.3 fail: Arvo's box with M's entries as they are, not their absolute values
// A negative entry then shrinks the half-extent: right for scales and turns whose matrix has
// no negative entry, too small for any other.
// @body
    const Vec3 centre = (box.min + box.max) * Real(0.5), half = (box.max - box.min) * Real(0.5);
    const Vec3 middle = to_world.point(centre), reach = glm::abs(to_world.m * half);
    Box result;
    result.min = middle - reach;
    result.max = middle + reach;
    return result;
