// Leaks and cost of the two ray-triangle tests, in the configured Real.
//
//   build/release/bin/bench_watertight [rays] [mesh.obj]
//   (build/float/bin/bench_watertight for Real=float)
//
// Rays aimed exactly at shared edges and vertices of closed meshes (see common/leaks.hpp):
// leaks, and nanoseconds per ray for each form, measured interleaved. With an OBJ path the
// mesh is measured too (only its interior edges count; an open mesh has no others).
#include "geometry/procedural.hpp"
#include "io/obj.hpp"
#include "support/leaks.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace rt;

int main(int argc, char** argv) {
    const long rays = argc > 1 ? std::atol(argv[1]) : 1000000;
    if (rays < 1) {
        std::fprintf(stderr, "usage: bench_watertight [rays >= 1] [mesh.obj]\n");
        return 2;
    }
    std::vector<std::pair<std::string, MeshData>> meshes = {
        {"icosphere/3 (1280 tris)", icosphere(Vec3(0.1, -0.2, 0.3), 1, 3)},
        {"cube 8x8 (768 tris)", subdivided_cube(Vec3(0.1, -0.2, 0.3), 1.7, 8)},
        {"icosphere/3 at 2^20", icosphere(Vec3(0x1p20, 0x1p20, 0), 1, 3)}};
    if (argc > 2) {
        try {
            meshes.emplace_back(argv[2], load_obj(argv[2]));
        } catch (const std::exception& e) {
            std::fprintf(stderr, "bench_watertight: %s\n", e.what());
            return 2;
        }
    }
    std::printf("Real=%s, %ld rays per mesh and form\n", real_name(), rays);
    std::printf("%-28s | %10s %8s | %10s %8s\n", "mesh", "Cramer", "ns/ray", "watertight", "ns/ray");
    for (const auto& [name, mesh] : meshes) {
        LeakReport r[2];
        double ns[2];
        const TriangleTest tests[2] = {TriangleTest::cramer, TriangleTest::watertight};
        for (int k = 0; k < 2; ++k) {
            const auto start = std::chrono::steady_clock::now();
            r[k] = measure_leaks(mesh, tests[k], rays, 1);
            ns[k] = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() /
                    double(rays);
        }
        std::printf("%-28s | %10ld %8.1f | %10ld %8.1f\n", name.c_str(), r[0].leaks, ns[0], r[1].leaks, ns[1]);
    }
    return 0;
}
