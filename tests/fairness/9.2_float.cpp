// fairness 9.2 fail: the normal carried in float, the precision of the library's colours
// Enough for a picture of the course's ellipsoid, but a normal rounded to float is 10^9 times
// coarser than the contract allows a Real=double build.
// @body
    const glm::mat3 m(glm::transpose(to_object.m));
    const glm::vec3 w = glm::normalize(m * glm::vec3(n));
    return Vec3(w);
