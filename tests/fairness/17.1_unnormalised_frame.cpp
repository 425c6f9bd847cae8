// fairness 17.1 fail: the course's frame without normalising U = e x r: its length is the sine
// of the angle between e and r (about 0.95 for a typical r), so the square of directions is
// narrower than `width`; V = r x U is as short. The worked value along +z, where e x r is
// already unit, does not show it; the lobe's spread does
// @body
    const Vec3 a = std::abs(r.x) <= std::abs(r.y) && std::abs(r.x) <= std::abs(r.z) ? Vec3(1, 0, 0)
                   : std::abs(r.y) <= std::abs(r.z)                                 ? Vec3(0, 1, 0)
                                                                                    : Vec3(0, 0, 1);
    const Vec3 u = glm::cross(a, r);
    const Vec3 v = glm::cross(r, u);
    return r + (uv.x - Real(0.5)) * width * u + (uv.y - Real(0.5)) * width * v;
