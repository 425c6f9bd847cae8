// fairness 2.1 pass: C factored as (|f| - R)(|f| + R)
// The same C, which subtracts numbers no larger than |f| + R; on a grazing ray whose |f| is not
// exact it rounds the discriminant another way than f.f - R^2 does (issue 42: 4.9999999999999991
// for 5 was rejected by an exact test).
// @body
    const Vec3& d = ray.direction;
    const Vec3 f = ray.origin - center;
    const Real dd = glm::dot(d, d);
    const Real b = glm::dot(d, f);
    const Real distance = glm::length(f);
    const Real c = (distance - radius) * (distance + radius);
    const Real discriminant = b * b - dd * c;
    if (discriminant < 0) return false;
    const Real root = std::sqrt(discriminant);
    t_near = (-b - root) / dd;
    t_far = (-b + root) / dd;
    return true;
