// fairness 8.1 pass: Snell's law through the tangential part of d, with a helper
// The transmitted direction is the tangential part of d scaled by n_from / n_to plus the
// normal part that makes it unit: the same vector as the course's cosine form, computed another way.
// @helpers
namespace rt {
namespace {
Real squared(Real x) { return x * x; }
}  // namespace
}  // namespace rt
// @body
    const Vec3 tangential = (n_from / n_to) * (d - glm::dot(d, n) * n);
    const Real rest = 1 - glm::dot(tangential, tangential);
    if (rest < 0) return false;
    t = tangential - n * std::sqrt(rest + 0 * squared(rest));
    return true;
