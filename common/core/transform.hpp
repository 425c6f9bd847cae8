#pragma once
// Affine transforms x -> M x + t, the matrices of instancing (book §9, course §9.8). Plain
// data: a 3x3 matrix and a translation, no homogeneous 4x4 to multiply by zeros.
#include "core/real.hpp"

#include <string>

namespace rt {

using Mat3 = glm::mat<3, 3, Real, glm::defaultp>;

struct Affine {
    Mat3 m{1};
    Vec3 t{0};

    Vec3 point(const Vec3& p) const { return m * p + t; }
    Vec3 vector(const Vec3& v) const { return m * v; }
    // This transform followed by `next`: (next * this) x.
    Affine then(const Affine& next) const { return Affine{next.m * m, next.m * t + next.t}; }
    bool is_identity() const { return m == Mat3(1) && t == Vec3(0); }

    static Affine scale(const Vec3& s) { return Affine{Mat3(s.x, 0, 0, 0, s.y, 0, 0, 0, s.z), Vec3(0)}; }
    static Affine translate(const Vec3& v) { return Affine{Mat3(1), v}; }
    // A right-handed rotation about `axis` (any non-zero length) by `degrees`.
    static Affine rotate(const Vec3& axis, Real degrees);
};

// The inverse transform. Throws std::invalid_argument, naming `what`, for a singular
// matrix (a scale of 0 flattens space, and nothing can be traced back through it) or a
// nearly singular one: condition number over 3 x 10^6 (a scale of 1e-6 on one axis passes).
Affine inverse(const Affine& a, const std::string& what = "transform");

}  // namespace rt
