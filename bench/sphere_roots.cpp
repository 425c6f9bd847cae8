// Time against error for the two ray-sphere root formulas, in the configured Real.
//
//   build/release/bin/bench_sphere_roots [rays] [rounds]
//   bench/real_choice.sh    (both Real types, side by side)
//
// For spheres D radii from the eye, rays aimed over 0.999 of the silhouette: nanoseconds per
// call (best of the interleaved rounds), worst relative error of t_near against a long-double
// reference, and the rays wrongly reported as misses.
#include "geometry/sphere.hpp"

#include <pcg_random.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <vector>

using namespace rt;

namespace {

using LVec = glm::vec<3, long double>;

long double reference_near(const Ray& r, const Vec3& c, Real R) {
    const LVec d(r.direction), f = LVec(r.origin) - LVec(c);
    const long double a = glm::dot(d, d), b = glm::dot(f, d), rr = R;
    const LVec foot = f - (b / a) * d;
    const long double h = std::sqrt(glm::dot(foot, foot));
    const long double disc = a * (rr - h) * (rr + h);
    if (disc < 0) return std::numeric_limits<long double>::quiet_NaN();
    const long double q = -(b + std::copysign(std::sqrt(disc), b));
    return std::min(q / a, (glm::dot(f, f) - rr * rr) / q);
}

struct Row {
    double ns = 1e300;
    double worst = 0;
    long misses = 0;
};

template <class Roots>
void measure(Roots roots, const std::vector<Ray>& rays, const Vec3& c, const std::vector<long double>& ref, Row& row) {
    Real sink = 0;
    long misses = 0;
    const auto start = std::chrono::steady_clock::now();
    for (const Ray& r : rays) {
        Real tn, tf;
        if (roots(r, c, Real(1), tn, tf))
            sink += tn;
        else
            ++misses;
    }
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() /
                      double(rays.size());
    row.ns = std::min(row.ns, ns);
    row.misses = misses;
    double worst = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        Real tn, tf;
        if (!roots(rays[i], c, Real(1), tn, tf) || std::isnan(double(ref[i]))) continue;
        worst = std::max(worst, double(std::fabs((tn - ref[i]) / ref[i])));
    }
    row.worst = worst;
    if (sink == Real(-1)) std::puts("");  // keep the loop
}

}  // namespace

int main(int argc, char** argv) {
    const int n = argc > 1 ? std::atoi(argv[1]) : 200000;
    const int rounds = argc > 2 ? std::atoi(argv[2]) : 5;
    if (n < 1 || rounds < 1) {
        std::fprintf(stderr, "usage: bench_sphere_roots [rays >= 1] [rounds >= 1]\n");
        return 2;
    }
    const double eps = std::numeric_limits<Real>::epsilon();
    std::printf("Real=%s, %d rays per distance, best of %d rounds\n", real_name(), n, rounds);
    std::printf("%10s | %9s %12s %8s | %9s %12s %8s\n", "D/R", "textbook", "worst err", "misses", "stable", "worst err",
                "misses");
    std::printf("%10s | %9s %12s %8s | %9s %12s %8s\n", "", "ns/ray", "(eps)", "", "ns/ray", "(eps)", "");
    for (double D : {1e1, 1e2, 1e3, 1e4, 1e5, 1e6}) {
        pcg32 rng(1);
        std::uniform_real_distribution<double> unit(0, 1);
        const Vec3 c = Vec3(glm::normalize(glm::dvec3(0.6, 0.3, -0.74)) * D);
        const Vec3 ahead = glm::normalize(c), side = glm::normalize(glm::cross(ahead, Vec3(0, 1, 0)));
        const Vec3 up = glm::cross(side, ahead);
        std::vector<Ray> rays;
        std::vector<long double> ref;
        for (int k = 0; k < n; ++k) {
            const double rad = 0.999 * std::sqrt(unit(rng)), phi = 2 * M_PI * unit(rng);
            rays.push_back(Ray{Vec3(0), c + Real(rad * std::cos(phi)) * side + Real(rad * std::sin(phi)) * up});
            ref.push_back(reference_near(rays.back(), c, 1));
        }
        Row textbook, stable;
        for (int r = 0; r < rounds; ++r) {  // interleaved, so both see the same machine load
            measure(sphere_roots_textbook, rays, c, ref, textbook);
            measure(sphere_roots, rays, c, ref, stable);
        }
        std::printf("%10.0e | %9.2f %12.3g %8ld | %9.2f %12.3g %8ld\n", D, textbook.ns, textbook.worst / eps,
                    textbook.misses, stable.ns, stable.worst / eps, stable.misses);
    }
    return 0;
}
