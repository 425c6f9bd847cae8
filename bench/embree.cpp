// The lab's fast path against Embree 3 (book §10.7), casting the same rays at the same
// triangles, one ray at a time on each side (rtcIntersect1 / rtcOccluded1), on 1 and 2
// threads, measured in the same run. Built only when Debian's libembree-dev is installed.
//
//   build/release/bin/bench_embree [--rounds N] [--size S] [--no-procedural] [--only TEXT] [--by-class]
//                                   [MESH.obj ...]
//
// Inputs: a terrain of ~10^5 and one of ~10^6 triangles, a soup of 10^6 triangles, and every
// OBJ given; --only keeps those whose name contains TEXT. Rays: the primary rays of an S x S
// camera (default 512) looking at the mesh, and shadow rays from each primary hit (the
// lab's, offset along the ray) towards a point light.
// For each input and thread count it prints Mrays/s of both and their ratio (best of N
// rounds, the two interleaved). Like for like, the lab's side of a primary ray is the mesh's
// own search, which gives what rtcIntersect1 gives (t, triangle, barycentrics); one more row
// times what the renderer calls, the search through the scene made into a whole HitRecord,
// against the same rtcIntersect1. Then build times (the lab's SAH, Embree's high-quality build),
// memory per triangle, and how often the two agree: hit or miss, and t to 1e-4 relative.
// --by-class adds, for the primary rays on one thread, nanoseconds per ray of each side for
// three kinds of ray apart: those that miss the mesh's box, those that enter it and miss,
// and those that hit (each kind timed alone, so the branch predictor sees one kind).
#include "accel/accel.hpp"
#include "geometry/procedural.hpp"
#include "io/obj.hpp"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

using namespace rt;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

std::atomic<long long> embree_bytes{0};

bool monitor(void*, ssize_t bytes, bool) {
    embree_bytes += bytes;
    return true;
}

struct EmbreeScene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    double build_seconds = 0;
    long long bytes = 0;

    EmbreeScene(const MeshData& mesh) {
        device = rtcNewDevice(nullptr);
        rtcSetDeviceMemoryMonitorFunction(device, monitor, nullptr);
        const long long before = embree_bytes;
        const auto start = Clock::now();
        scene = rtcNewScene(device);
        rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), mesh.positions.size()));
        for (std::size_t k = 0; k < mesh.positions.size(); ++k)
            for (int a = 0; a < 3; ++a) v[3 * k + std::size_t(a)] = float(mesh.positions[k][a]);
        auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(unsigned), mesh.triangles.size()));
        for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
            for (int a = 0; a < 3; ++a) t[3 * k + std::size_t(a)] = mesh.triangles[k][std::size_t(a)];
        rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_HIGH);
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene, geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(scene);
        build_seconds = seconds_since(start);
        bytes = embree_bytes - before;
    }
    ~EmbreeScene() {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }

    float hit(const Ray& r, float tfar) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh{};
        rh.ray.org_x = float(r.origin.x);
        rh.ray.org_y = float(r.origin.y);
        rh.ray.org_z = float(r.origin.z);
        rh.ray.dir_x = float(r.direction.x);
        rh.ray.dir_y = float(r.direction.y);
        rh.ray.dir_z = float(r.direction.z);
        rh.ray.tnear = 0;
        rh.ray.tfar = tfar;
        rh.ray.mask = ~0u;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &context, &rh);
        return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? std::numeric_limits<float>::infinity() : rh.ray.tfar;
    }
    bool occluded(const Ray& r, float tfar) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay ray{};
        ray.org_x = float(r.origin.x);
        ray.org_y = float(r.origin.y);
        ray.org_z = float(r.origin.z);
        ray.dir_x = float(r.direction.x);
        ray.dir_y = float(r.direction.y);
        ray.dir_z = float(r.direction.z);
        ray.tnear = 0;
        ray.tfar = tfar;
        ray.mask = ~0u;
        rtcOccluded1(scene, &context, &ray);
        return ray.tfar < 0;  // Embree sets tfar to -inf when something is in the way
    }
};

// Seconds for `work(begin, end)` over n rays on `threads` threads, in chunks of 4096.
double timed(int threads, std::size_t n, const std::function<void(std::size_t, std::size_t)>& work) {
    tbb::task_arena arena(threads);
    const auto start = Clock::now();
    arena.execute([&] {
        // Small chunks handed out as threads ask (rays cost from a few to hundreds of
        // nanoseconds, row by row), so that neither thread waits long for the other at the end.
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, n, 1024),
            [&](const tbb::blocked_range<std::size_t>& r) { work(r.begin(), r.end()); }, tbb::simple_partitioner());
    });
    return seconds_since(start);
}

struct Input {
    std::string name;
    MeshData mesh;
};

constexpr float kFar = std::numeric_limits<float>::infinity();

// The lab's side of a primary ray, like rtcIntersect1: the closest hit's t, triangle and
// barycentrics, from the mesh's own search.
bool lab_primary(const Mesh& mesh, const Ray& r) {
    MeshHit h;
    return hit(mesh, r, Interval{}, h);
}

// Nanoseconds per primary ray on one thread, by kind of ray (--by-class).
void by_class(const Accel& accel, const SurfaceList& list, const Mesh& mesh, const EmbreeScene& embree,
              const std::vector<Ray>& primary, int rounds) {
    std::vector<Ray> kind[3];
    for (const Ray& r : primary) {
        HitRecord rec;
        kind[!might_hit(mesh.box(), r, Interval{}) ? 0 : accel.hit(list, r, Interval{}, rec) ? 2 : 1].push_back(r);
    }
    const char* names[3] = {"miss the box", "enter, miss", "hit"};
    std::atomic<long> sink{0};
    std::printf("  primary rays by kind, 1 thread: %-14s %7s %10s %10s %7s\n", "", "rays", "lab ns", "Embree ns",
                "ratio");
    for (int k = 0; k < 3; ++k) {
        const std::vector<Ray>& rays = kind[k];
        if (rays.empty()) continue;
        double lab = 1e30, emb = 1e30;
        for (int round = 0; round < rounds; ++round) {
            lab = std::min(lab, timed(1, rays.size(), [&](std::size_t b, std::size_t e) {
                               long n = 0;
                               for (std::size_t i = b; i < e; ++i) n += lab_primary(mesh, rays[i]);
                               sink += n;
                           }));
            emb = std::min(emb, timed(1, rays.size(), [&](std::size_t b, std::size_t e) {
                               long n = 0;
                               for (std::size_t i = b; i < e; ++i) n += std::isfinite(embree.hit(rays[i], kFar));
                               sink += n;
                           }));
        }
        const double per = 1e9 / double(rays.size());
        std::printf("  %-47s %7zu %10.1f %10.1f %7.2f\n", names[k], rays.size(), lab * per, emb * per, emb / lab);
    }
}

void measure(const Input& input, int size, int rounds, bool classes) {
    const auto lab_start = Clock::now();
    SurfaceList list;
    list.add(Mesh(input.mesh));
    const Accel accel(list, AccelKind::fast);
    const double lab_build = seconds_since(lab_start);
    const Mesh& mesh = std::get<Mesh>(list[0].shape);
    const std::size_t triangles = mesh.data().triangles.size();
    const double lab_bytes = double(accel.info().bytes + memory_bytes(mesh.data()));
    const EmbreeScene embree(mesh.data());

    // A camera on the diagonal above the mesh's box, its whole box in view.
    const Box box = mesh.box();
    const Vec3 centre = (box.min + box.max) * Real(0.5), extent = box.max - box.min;
    const Real reach = glm::length(extent);
    const Vec3 eye = centre + Vec3(0.5, 0.8, 0.7) * reach;
    const Vec3 w = glm::normalize(eye - centre), u = glm::normalize(glm::cross(Vec3(0, 1, 0), w)), v = glm::cross(w, u);
    std::vector<Ray> primary;
    primary.reserve(std::size_t(size) * std::size_t(size));
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const Real x = (Real(i) + Real(0.5)) / Real(size) - Real(0.5);
            const Real y = (Real(j) + Real(0.5)) / Real(size) - Real(0.5);
            primary.push_back(Ray{eye, x * Real(0.9) * u + y * Real(0.9) * v - w});
        }
    // Shadow rays: from each lab hit, nudged back along the ray, to a light above.
    const Vec3 light = centre + Vec3(-0.3, 1.2, 0.4) * reach;
    std::vector<Ray> shadow;
    int agree = 0, t_agree = 0, both_hit = 0;
    for (const Ray& r : primary) {
        HitRecord rec;
        const bool lab_hit = accel.hit(list, r, Interval{}, rec);
        const float e = embree.hit(r, std::numeric_limits<float>::infinity());
        const bool embree_hit = std::isfinite(e);
        agree += lab_hit == embree_hit;
        if (lab_hit && embree_hit) {
            ++both_hit;
            t_agree += std::abs(double(e) - double(rec.t)) <= 1e-4 * double(rec.t);
            const Vec3 p = r.at(rec.t * Real(0.9999));
            shadow.push_back(Ray{p, light - p});
        }
    }
    int shadow_agree = 0;
    for (const Ray& r : shadow) shadow_agree += accel.occluded(list, r, Interval{0, 1}) == embree.occluded(r, 1.0f);

    std::printf("\n%s: %zu triangles; %zu primary rays (%d hit), %zu shadow rays\n", input.name.c_str(), triangles,
                primary.size(), both_hit, shadow.size());
    std::printf(
        "  build: lab SAH %.3f s, Embree high quality %.3f s; memory per triangle: lab %.1f B (mesh + BVH), "
        "Embree %.1f B\n",
        lab_build, embree.build_seconds, lab_bytes / double(triangles), double(embree.bytes) / double(triangles));
    std::printf("  agreement: hit/miss %.4f %%, t within 1e-4 %.4f %% of common hits, shadow %.4f %%\n",
                100.0 * agree / double(primary.size()), both_hit ? 100.0 * t_agree / both_hit : 100.0,
                shadow.empty() ? 100.0 : 100.0 * shadow_agree / double(shadow.size()));
    if (classes) by_class(accel, list, mesh, embree, primary, rounds);
    std::printf("  %-22s %7s %12s %12s %7s\n", "rays", "threads", "lab Mrays/s", "Embree", "ratio");
    std::atomic<long> sink{0};
    // One row: Mrays/s of each side on 1 and 2 threads, best of the rounds, the two interleaved.
    const auto row = [&](const char* name, const std::vector<Ray>& rays, auto&& lab_ray, auto&& embree_ray) {
        if (rays.empty()) return;
        for (int threads : {1, 2}) {
            double lab = 1e30, emb = 1e30;
            for (int round = 0; round < rounds; ++round) {
                lab = std::min(lab, timed(threads, rays.size(), [&](std::size_t b, std::size_t e) {
                                   long n = 0;
                                   for (std::size_t k = b; k < e; ++k) n += lab_ray(rays[k]);
                                   sink += n;
                               }));
                emb = std::min(emb, timed(threads, rays.size(), [&](std::size_t b, std::size_t e) {
                                   long n = 0;
                                   for (std::size_t k = b; k < e; ++k) n += embree_ray(rays[k]);
                                   sink += n;
                               }));
            }
            const double lab_m = double(rays.size()) / lab / 1e6, emb_m = double(rays.size()) / emb / 1e6;
            std::printf("  %-22s %7d %12.2f %12.2f %7.2f\n", name, threads, lab_m, emb_m, lab_m / emb_m);
            std::fflush(stdout);
        }
    };
    const auto embree_primary = [&](const Ray& r) { return std::isfinite(embree.hit(r, kFar)); };
    // Like for like: each side finds the closest hit and gives its t, triangle and
    // barycentrics (the mesh's own search: the fast path's lower level, all of it for a
    // scene of one mesh), or answers whether anything blocks a shadow ray.
    row(
        "primary", primary, [&](const Ray& r) { return lab_primary(mesh, r); }, embree_primary);
    row(
        "shadow", shadow,
        [&](const Ray& r) {
            return occluded(mesh, r, Interval{0, 1});
        },
        [&](const Ray& r) { return embree.occluded(r, 1.0f); });
    // What the renderer calls: the closest hit through the scene's search, made into the
    // whole HitRecord (point, unit normal, surface) that shading reads. Embree's side is the
    // same rtcIntersect1 as above: what it returns is not a record.
    row(
        "primary, HitRecord", primary,
        [&](const Ray& r) {
            HitRecord rec;
            return accel.hit(list, r, Interval{}, rec);
        },
        embree_primary);
}

}  // namespace

int main(int argc, char** argv) {
    int rounds = 5, size = 512;
    bool procedural = true, classes = false;
    std::string only;
    std::vector<Input> inputs;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        try {
            if (a == "--rounds" && i + 1 < argc) {
                rounds = std::max(1, std::atoi(argv[++i]));
            } else if (a == "--size" && i + 1 < argc) {
                size = std::max(16, std::atoi(argv[++i]));
            } else if (a == "--only" && i + 1 < argc) {
                only = argv[++i];
            } else if (a == "--by-class") {
                classes = true;
            } else if (a == "--no-procedural") {
                procedural = false;
            } else if (!a.empty() && a[0] != '-') {
                inputs.push_back({a.substr(a.find_last_of('/') + 1), load_obj(a)});
            } else {
                std::fprintf(stderr,
                             "usage: bench_embree [--rounds N] [--size S] [--no-procedural] [--only TEXT] [--by-class] "
                             "[MESH.obj ...]\n");
                return 2;
            }
        } catch (const std::exception& e) {
            std::fprintf(stderr, "bench_embree: %s\n", e.what());
            return 2;
        }
    }
    if (procedural) {
        inputs.insert(inputs.begin(), {{"terrain 10^5", terrain(Vec3(0), 10, 1.5, 224)},
                                       {"terrain 10^6", terrain(Vec3(0), 10, 1.5, 707)},
                                       {"soup 10^6", triangle_soup(Vec3(0), 10, 0.1, 1000000, 3)}});
    }
    // The same triangles on both sides: Embree takes float vertices, so the lab's are rounded
    // to float too (which also lets its exact test read them from its blocks: TriangleBlock).
    for (Input& in : inputs)
        for (Vec3& p : in.mesh.positions) p = Vec3(round_to_float(p.x), round_to_float(p.y), round_to_float(p.z));
    std::printf(
        "lab: Real=%s, fast path (two-level: 8-wide float BVH with 4-triangle blocks in each mesh, binary over the "
        "surfaces); Embree %d.%d.%d, "
        "rtcIntersect1/rtcOccluded1\n",
        real_name(), RTC_VERSION_MAJOR, RTC_VERSION_MINOR, RTC_VERSION_PATCH);
    for (const Input& in : inputs)
        if (in.name.find(only) != std::string::npos) measure(in, size, rounds, classes);
    return 0;
}
