#pragma once
// The bounds bench/bounding_volumes.cpp sets against boxes (book §10.8): a ball and an
// ellipsoid, their fits around a set of points, and the ray tests a hierarchy would make.
#include "core/ray.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rt::bench {

struct Ball {
    Vec3 c;
    Real r;
};
// The ellipsoid {x : |M (x - c)| <= 1}.
struct Ellipsoid {
    glm::dmat3 m;
    Vec3 c;
};

// Does the ray meet the ball for some t in [lo, hi]? Only what a bound needs: no roots
// computed with care, since a near miss either way costs one extra or one fewer test.
inline bool hit_ball(const Vec3& c, Real r, const Vec3& o, const Vec3& d, Real lo, Real hi) {
    const Vec3 oc = c - o;
    const Real a = glm::dot(d, d), b = glm::dot(oc, d), q = glm::dot(oc, oc) - r * r;
    const Real disc = b * b - a * q;
    if (disc < 0) return false;
    const Real s = std::sqrt(disc);
    return (b + s) >= lo * a && (b - s) <= hi * a;
}
inline bool hit_ellipsoid(const Ellipsoid& e, const Ray& ray, Real lo, Real hi) {
    const glm::dmat3 m = e.m;
    return hit_ball(Vec3(0), 1, Vec3(m * glm::dvec3(ray.origin - e.c)), Vec3(m * glm::dvec3(ray.direction)), lo, hi);
}
// Where the ray enters the ball (its near root, or 0 from inside), or +inf.
inline Real enter_ball(const Ball& s, const Ray& ray, Real hi) {
    const Vec3 oc = s.c - ray.origin;
    const Real a = glm::dot(ray.direction, ray.direction), b = glm::dot(oc, ray.direction);
    const Real disc = b * b - a * (glm::dot(oc, oc) - s.r * s.r);
    if (disc < 0) return kInfinity;
    const Real sq = std::sqrt(disc), t0 = (b - sq) / a, t1 = (b + sq) / a;
    if (t1 < 0 || t0 > hi) return kInfinity;
    return std::max(t0, Real(0));
}

inline Ball ritter(const std::vector<Vec3>& p) {
    auto farthest = [&](const Vec3& from) {
        return *std::max_element(p.begin(), p.end(), [&](const Vec3& a, const Vec3& b) {
            return glm::dot(a - from, a - from) < glm::dot(b - from, b - from);
        });
    };
    const Vec3 x = farthest(p[0]), y = farthest(x);
    Ball s{(x + y) * Real(0.5), glm::length(y - x) * Real(0.5)};
    for (const Vec3& q : p) {
        const Real d = glm::length(q - s.c);
        if (d > s.r) {  // grow just enough to take q in
            const Real r = (s.r + d) * Real(0.5);
            s.c += (q - s.c) * ((r - s.r) / d);
            s.r = r;
        }
    }
    s.r *= 1 + 1e-12;  // rounding: every point inside
    return s;
}

inline Real radius_about(const std::vector<Vec3>& p, const Vec3& c) {
    Real r2 = 0;
    for (const Vec3& q : p) r2 = std::max(r2, glm::dot(q - c, q - c));
    return std::sqrt(r2) * (1 + 1e-12);
}

// Badoiu and Clarkson: step towards the farthest point by 1/(i+1); after k steps the ball
// about the centre is within a factor 1 + 1/sqrt(k) of the smallest (their bound): 5 % here.
// Ritter's ball is kept when it is smaller.
inline Ball near_smallest_ball(const std::vector<Vec3>& p) {
    Ball best = ritter(p);
    Vec3 c = best.c;
    for (int i = 1; i <= 400; ++i) {
        const Vec3 far = *std::max_element(p.begin(), p.end(), [&](const Vec3& a, const Vec3& b) {
            return glm::dot(a - c, a - c) < glm::dot(b - c, b - c);
        });
        c += (far - c) / Real(i + 1);
        if (i % 50 == 0) {
            const Real r = radius_about(p, c);
            if (r < best.r) best = {c, r};
        }
    }
    return best;
}

// Khachiyan's minimum-volume enclosing ellipsoid, to a tolerance, then scaled so that every
// point is inside.
inline Ellipsoid min_ellipsoid(const std::vector<Vec3>& p) {
    const std::size_t n = p.size();
    std::vector<double> u(n, 1.0 / double(n));
    glm::dmat4 x(0.0);  // sum of u_i q_i q_i^T, kept up to date as u changes
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec4 q(p[i], 1.0);
        x += u[i] * glm::outerProduct(q, q);
    }
    for (int it = 0; it < 4000; ++it) {
        const glm::dmat4 xi = glm::inverse(x);
        double worst = 0;
        std::size_t j = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const glm::dvec4 q(p[i], 1.0);
            const double m = glm::dot(q, xi * q);
            if (m > worst) worst = m, j = i;
        }
        const double step = (worst - 4) / (4 * (worst - 1));
        if (step < 1e-4) break;
        for (double& w : u) w *= 1 - step;
        u[j] += step;
        const glm::dvec4 q(p[j], 1.0);
        x = (1 - step) * x + step * glm::outerProduct(q, q);
    }
    glm::dvec3 c(0.0);
    for (std::size_t i = 0; i < n; ++i) c += u[i] * glm::dvec3(p[i]);
    glm::dmat3 cov(0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 q = glm::dvec3(p[i]) - c;
        cov += u[i] * glm::outerProduct(q, q);
    }
    glm::dmat3 a = glm::inverse(cov) / 3.0;  // (x - c)^T a (x - c) <= 1
    double worst = 0;
    for (const Vec3& q : p) worst = std::max(worst, glm::dot(glm::dvec3(q) - c, a * (glm::dvec3(q) - c)));
    a /= worst * (1 + 1e-12);
    // M with M^T M = a: a's square root through its eigenvectors would do; Cholesky is enough.
    const double l00 = std::sqrt(a[0][0]), l10 = a[0][1] / l00, l20 = a[0][2] / l00;
    const double l11 = std::sqrt(a[1][1] - l10 * l10), l21 = (a[1][2] - l20 * l10) / l11;
    const double l22 = std::sqrt(a[2][2] - l20 * l20 - l21 * l21);
    // glm is column-major: m[col][row]. M = L^T (upper), so |M v|^2 = v^T L L^T v = v^T a v.
    glm::dmat3 m(0.0);
    m[0][0] = l00, m[1][0] = l10, m[2][0] = l20, m[1][1] = l11, m[2][1] = l21, m[2][2] = l22;
    return {m, Vec3(c)};
}

}  // namespace rt::bench
