// The course's exercise 3 made real (book §10.7, §11.5): how build time and time per ray grow
// with the number of triangles, for brute force and each structure, on procedural meshes
// (terrains), on triangle soups, 10^2 ... 10^6 triangles, and on the teapot in a stadium (a
// dense ball of ~N triangles on a floor 1,000 times its size; rays aimed at the ball).
//
//   build/release/bin/bench_complexity [--max N] [--rays R] [--csv FILE]
//
// Prints a table and writes CSV rows: input,triangles,structure,build_s,ns_per_ray,
// nodes_per_ray,primitives_per_ray,bytes_per_primitive. The same rays go to every structure
// of one input, interleaved structure by structure, and each must return brute force's hits
// (checked where brute force runs). Brute force is capped: it stops at 10^4 triangles with
// all rays, and tests a tenth of the rays at 10^5 (a single run there takes seconds).
// ./lab bench complexity runs it and plots the CSV (bench/complexity.gnuplot).
#include "accel/accel.hpp"
#include "fit.hpp"
#include "geometry/procedural.hpp"

#include <pcg_random.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace rt;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Rays from a ring of eye points around the mesh towards random points of its box: most hit,
// some graze, some miss, as a camera's would.
std::vector<Ray> make_rays(const Box& box, int n) {
    pcg32 gen(10);
    std::uniform_real_distribution<Real> u(0, 1);
    const Vec3 centre = (box.min + box.max) * Real(0.5), size = box.max - box.min;
    const Real reach = glm::length(size);
    std::vector<Ray> rays;
    rays.reserve(std::size_t(n));
    for (int k = 0; k < n; ++k) {
        const Real angle = Real(6.283185307179586) * u(gen), height = u(gen);
        const Vec3 eye = centre + Vec3(std::cos(angle) * reach, (Real(0.3) + height) * reach, std::sin(angle) * reach);
        const Real a = u(gen), b = u(gen), c = u(gen);
        const Vec3 target = box.min + size * Vec3(a, b, c);
        rays.push_back(Ray{eye, target - eye});
    }
    return rays;
}

struct Row {
    std::string input;
    std::size_t triangles;
    std::string structure;
    double build_s, ns_per_ray, nodes_per_ray, primitives_per_ray, bytes_per_primitive;
};

}  // namespace

int main(int argc, char** argv) {
    long max_triangles = 1000000, ray_count = 20000;
    std::string csv_path;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--max" && i + 1 < argc)
            max_triangles = std::atol(argv[++i]);
        else if (a == "--rays" && i + 1 < argc)
            ray_count = std::atol(argv[++i]);
        else if (a == "--csv" && i + 1 < argc)
            csv_path = argv[++i];
        else {
            std::fprintf(stderr, "usage: bench_complexity [--max N] [--rays R] [--csv FILE]\n");
            return 2;
        }
    }
    if (max_triangles < 100 || ray_count < 100) {
        std::fprintf(stderr, "bench_complexity: --max must be >= 100 and --rays >= 100\n");
        return 2;
    }

    std::vector<Row> rows;
    std::printf("Real=%s, %ld rays per input; brute force capped (see the source)\n", real_name(), ray_count);
    std::printf("%-8s %9s %-13s %10s %10s %9s %9s %9s\n", "input", "triangles", "structure", "build s", "ns/ray",
                "nodes/ray", "prims/ray", "B/prim");
    int failures = 0;
    for (const char* input : {"terrain", "soup", "stadium"}) {
        for (long n = 100; n <= max_triangles; n *= 10) {
            // A terrain of c x c cells has 2c^2 triangles; a soup has exactly n.
            const int cells = std::max(1, int(std::lround(std::sqrt(double(n) / 2))));
            const auto build_start = std::chrono::steady_clock::now();
            SurfaceList list;
            Box target;  // where the rays aim
            if (std::strcmp(input, "terrain") == 0) {
                list.add(Mesh(terrain(Vec3(0), 10, 1.5, cells)));
            } else if (std::strcmp(input, "soup") == 0) {
                list.add(Mesh(triangle_soup(Vec3(0), 10, Real(10) / Real(std::cbrt(double(n))), int(n), 3)));
            } else {
                // An icosphere of 20 * 4^s triangles, the s nearest to n (at most 7: 327,680), on
                // a 1000-wide floor.
                const int s = std::clamp(int(std::lround(std::log(double(n) / 20) / std::log(4.0))), 1, 7);
                list.add(Mesh(icosphere(Vec3(0, 1, 0), 1, s)));
                target = list.bounding_box();
                list.add(Polygon({Vec3(-500, 0, -500), Vec3(-500, 0, 500), Vec3(500, 0, 500), Vec3(500, 0, -500)}));
            }
            // The mesh's own BVH (the fast path's lower level) is built with the mesh.
            const double mesh_build = seconds_since(build_start);
            const std::size_t triangles = primitives_of(list).size();
            const std::vector<Ray> rays = make_rays(target.empty() ? list.bounding_box() : target, int(ray_count));

            std::vector<HitRecord> reference;
            for (AccelKind kind : kAccelKinds) {
                std::size_t use = rays.size();
                if (kind == AccelKind::none) {
                    if (triangles > 200000) continue;
                    if (triangles > 20000) use = rays.size() / 10;
                }
                const Accel accel(list, kind);
                const double build = accel.info().build_seconds + (kind == AccelKind::fast ? mesh_build : 0.0);
                std::vector<HitRecord> hits(use);
                // One untimed pass first: the structures built before this one have pushed its
                // memory out of the caches (and, for the biggest meshes, out of the TLB), and
                // that one-off cost would otherwise dominate 20,000 rays. Steady state is what
                // a render sees.
                for (std::size_t k = 0; k < use; ++k) accel.hit(list, rays[k], Interval{}, hits[k]);
                traversal_tally = {};
                const auto start = std::chrono::steady_clock::now();
                for (std::size_t k = 0; k < use; ++k)
                    if (!accel.hit(list, rays[k], Interval{}, hits[k])) hits[k].t = kInfinity;
                const double seconds = seconds_since(start);
                if (reference.empty()) {
                    reference = hits;
                } else {
                    for (std::size_t k = 0; k < std::min(use, reference.size()); ++k)
                        if (hits[k].t != reference[k].t || hits[k].primitive != reference[k].primitive) ++failures;
                }
                const AccelInfo& info = accel.info();
                std::size_t bytes = info.bytes;
                if (kind == AccelKind::none) bytes = 0;
                Row r{input,
                      triangles,
                      kAccelNames[kind],
                      build,
                      seconds / double(use) * 1e9,
                      double(traversal_tally.nodes) / double(use),
                      double(traversal_tally.items) / double(use),
                      double(bytes) / double(triangles)};
                std::printf("%-8s %9zu %-13s %10.4f %10.1f %9.1f %9.1f %9.1f\n", r.input.c_str(), r.triangles,
                            r.structure.c_str(), r.build_s, r.ns_per_ray, r.nodes_per_ray, r.primitives_per_ray,
                            r.bytes_per_primitive);
                std::fflush(stdout);
                rows.push_back(r);
            }
        }
    }

    // Slopes of log(time) against log(triangles), by least squares: the exponents the course
    // predicts are 1 for brute force's query, 0 (log N) for a tree's, and about 1 (N log N)
    // for building.
    std::printf("\nslopes of log-log fits over the sizes measured (query, build):\n");
    for (const char* input : {"terrain", "soup", "stadium"})
        for (AccelKind kind : kAccelKinds) {
            std::vector<double> n, query, build;
            for (const Row& r : rows)
                if (r.input == input && r.structure == kAccelNames[kind] && r.build_s > 0) {
                    n.push_back(double(r.triangles));
                    query.push_back(r.ns_per_ray);
                    build.push_back(std::max(r.build_s, 1e-7));
                }
            if (n.size() < 2) continue;
            std::printf("  %-8s %-13s query %5.2f  build %5.2f\n", input, kAccelNames[kind],
                        bench::loglog_slope(n, query), kind == AccelKind::none ? 0.0 : bench::loglog_slope(n, build));
        }

    if (!csv_path.empty()) {
        std::ofstream csv(csv_path);
        csv << "input,triangles,structure,build_s,ns_per_ray,nodes_per_ray,primitives_per_ray,bytes_per_primitive\n";
        for (const Row& r : rows)
            csv << r.input << ',' << r.triangles << ',' << r.structure << ',' << r.build_s << ',' << r.ns_per_ray << ','
                << r.nodes_per_ray << ',' << r.primitives_per_ray << ',' << r.bytes_per_primitive << '\n';
        if (!csv) {
            std::fprintf(stderr, "bench_complexity: cannot write %s\n", csv_path.c_str());
            return 1;
        }
    }
    if (failures) {
        std::fprintf(stderr, "bench_complexity: %d hits differ from the first structure's\n", failures);
        return 1;
    }
    return 0;
}
