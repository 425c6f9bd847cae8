// The lab's fast path against Embree 3 (book §10.7), casting the same rays at the same
// triangles, one ray at a time on each side (rtcIntersect1 / rtcOccluded1), on 1 and 2
// threads, measured in the same run. Built only when Debian's libembree-dev is installed.
//
//   build/release/bin/bench_embree [--rounds N] [--size S] [--frame F] [--no-procedural] [--only TEXT]
//                                   [--by-class] [--instructions N] [MESH.obj ...]
//
// Inputs: a terrain of ~10^5 and one of ~10^6 triangles, a soup of 10^6 triangles, and every
// OBJ given; --only keeps those whose name contains TEXT. Rays: the primary rays of an S x S
// camera (default 512) looking at the mesh, and shadow rays from each primary hit (the
// lab's, offset along the ray) towards a point light.
// For each input it prints first the build times on 1 and 2 threads (the lab's SAH build,
// Embree's high-quality build, each inside a TBB task arena of that many threads), memory per
// triangle, and how often the two agree: hit or miss, and t to 1e-4 relative. Then, for each
// thread count, Mrays/s of both and their ratio (best of N rounds, the two interleaved). Like
// for like, the lab's side of a primary ray is the mesh's own search, which gives what
// rtcIntersect1 gives (t, triangle, barycentrics); one more row times what the renderer
// calls, the search through the scene made into a whole HitRecord, against the same
// rtcIntersect1. Then the rows of a frame, F x F (default 1024; 0 leaves them out) shaded by
// normals: "frame rays, search", the frame's camera rays searched as the render searches them
// (eight at a time, Scene::hit_packet, book §10.5) against rtcIntersect1 on each; "frame
// rays, packets", the same against Embree's own packets of the same eight (rtcIntersect8);
// and "whole frame", a chapter program's whole render against rtcIntersect1 on its rays.
// --by-class adds, for the primary rays on one thread, nanoseconds per ray of each side for
// three kinds of ray apart: those that miss the mesh's box, those that enter it and miss,
// and those that hit (each kind timed alone, so the branch predictor sees one kind).
// --instructions N times nothing: it casts each kind of ray N times for callgrind to count
// (count() below; bench/embree_instructions.sh).
#include "accel/accel.hpp"
#include "geometry/procedural.hpp"
#include "io/obj.hpp"
#include "render/first_hit.hpp"
#include "render/integrators.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"

#include <embree3/rtcore.h>
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else  // without valgrind's header, --instructions casts the rays and nothing counts them
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#define CALLGRIND_DUMP_STATS_AT(name) (void)(name)
#endif
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <vector>

using namespace rt;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

std::atomic<long long> embree_bytes{0};

constexpr float kFar = std::numeric_limits<float>::infinity();

bool monitor(void*, ssize_t bytes, bool) {
    embree_bytes += bytes;
    return true;
}

struct EmbreeScene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    double build_seconds = 0;
    long long bytes = 0;

    // Built inside a task arena of `threads`: Embree's TBB tasks run in the caller's arena.
    EmbreeScene(const MeshData& mesh, int threads) {
        tbb::task_arena(threads).execute([&] { build(mesh); });
    }
    void build(const MeshData& mesh) {
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
    // Up to eight rays at once (rtcIntersect8, told they are coherent: a camera's); how many hit.
    int hit8(const Ray* rays, int n) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        alignas(32) int valid[8];
        alignas(32) RTCRayHit8 rh;
        for (int k = 0; k < 8; ++k) {
            valid[k] = k < n ? -1 : 0;
            const Ray& r = rays[k < n ? k : 0];
            rh.ray.org_x[k] = float(r.origin.x);
            rh.ray.org_y[k] = float(r.origin.y);
            rh.ray.org_z[k] = float(r.origin.z);
            rh.ray.dir_x[k] = float(r.direction.x);
            rh.ray.dir_y[k] = float(r.direction.y);
            rh.ray.dir_z[k] = float(r.direction.z);
            rh.ray.tnear[k] = 0;
            rh.ray.tfar[k] = kFar;
            rh.ray.mask[k] = ~0u;
            rh.ray.time[k] = 0;
            rh.ray.flags[k] = 0;
            rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
        }
        rtcIntersect8(valid, scene, &context, &rh);
        int hits = 0;
        for (int k = 0; k < n; ++k) hits += rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID;
        return hits;
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

// Seconds for `work(begin, end)` over n rays on `threads` threads, in chunks of `grain`.
double timed(int threads, std::size_t n, const std::function<void(std::size_t, std::size_t)>& work,
             std::size_t grain = 1024) {
    tbb::task_arena arena(threads);
    const auto start = Clock::now();
    arena.execute([&] {
        // Small chunks handed out as threads ask (rays cost from a few to hundreds of
        // nanoseconds, row by row), so that neither thread waits long for the other at the end.
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, n, grain),
            [&](const tbb::blocked_range<std::size_t>& r) { work(r.begin(), r.end()); }, tbb::simple_partitioner());
    });
    return seconds_since(start);
}

struct Input {
    std::string name;
    MeshData mesh;
};

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

// The lab's side of a build: the mesh (its SAH tree, collapsed to the wide one, and its
// triangle blocks) and the scene's structure over it, inside a task arena of `threads`.
struct LabScene {
    SurfaceList list;
    std::optional<Accel> accel;
    double build_seconds = 0;

    LabScene(const MeshData& data, int threads) {
        tbb::task_arena arena(threads);
        const auto start = Clock::now();
        arena.execute([&] {
            list.add(Mesh(data));
            accel.emplace(list, AccelKind::fast);
        });
        build_seconds = seconds_since(start);
    }
};

// A chapter program's frame (ChapterApp::execute without the image file): the scene as a
// scene file with "shading": "normal" makes it, the camera looking at the mesh's box from
// `eye`, its field of view the one the primary rays above span, one sample per pixel.
Scene frame_scene(const Mesh& mesh, const Vec3& eye, const Vec3& centre) {
    Scene scene =
        look_at(eye, centre, Real(2 * std::atan(0.45) * 180 / std::numbers::pi), make_integrator(Shading::normal));
    scene.surfaces.add(mesh);  // a copy shares the mesh's data and tree
    scene.build_accel(scene.accel_kind);
    return scene;
}

// --instructions N: each kind of ray cast N times on one thread, each side alone, between
// callgrind's start and stop of instrumentation, and a dump of the counts named after it
// ("INPUT: KIND, SIDE, N x RAYS rays"): run under valgrind --tool=callgrind
// --instr-atstart=no, each dump holds the instructions of those casts and nothing else
// (bench/embree_instructions.sh divides them by the rays).
template <class Batch>
void count_batch(const std::string& input, const char* kind, const char* side, std::size_t rays, int repeats,
                 Batch&& batch) {
    if (rays == 0) return;
    long n = 0;
    traversal_tally = {};
    CALLGRIND_START_INSTRUMENTATION;
    for (int k = 0; k < repeats; ++k) n += batch();
    CALLGRIND_STOP_INSTRUMENTATION;
    const std::string name =
        input + ": " + kind + ", " + side + ", " + std::to_string(repeats) + " x " + std::to_string(rays) + " rays";
    CALLGRIND_DUMP_STATS_AT(name.c_str());
    const double casts = double(repeats) * double(rays);
    std::printf("  counted %s (%ld answered yes; the lab's tally per ray: %.1f boxes, %.1f triangles)\n", name.c_str(),
                n, double(traversal_tally.nodes) / casts, double(traversal_tally.items) / casts);
}

template <class Cast>
void count(const std::string& input, const char* kind, const char* side, const std::vector<Ray>& rays, int repeats,
           Cast&& cast) {
    count_batch(input, kind, side, rays.size(), repeats, [&] {
        long n = 0;
        for (const Ray& r : rays) n += cast(r);
        return n;
    });
}

// The camera rays of an F x F frame, in the order the render casts them: tiles of 16 x 16
// pixels (render/render.cpp's), each in packets of kPacketRows x kPacketColumns pixels
// (render/first_hit.hpp), row by row within a packet; `packets` holds each packet's first ray
// and, last, the number of rays. Embree's side meets the same rays in the same memory order.
constexpr int kTile = 16;  // render/render.cpp's
struct FrameRays {
    std::vector<Ray> rays;
    std::vector<std::size_t> packets;
    std::size_t packet_count() const { return packets.size() - 1; }
    std::span<const Ray> packet(std::size_t k) const {
        return std::span(rays).subspan(packets[k], packets[k + 1] - packets[k]);
    }
};
FrameRays frame_rays(const Scene& scene, int frame) {
    const View view = scene.camera.view(frame, frame);
    FrameRays f;
    f.rays.reserve(std::size_t(frame) * std::size_t(frame));
    for (int y0 = 0; y0 < frame; y0 += kTile)
        for (int x0 = 0; x0 < frame; x0 += kTile)
            for (int py = y0; py < std::min(y0 + kTile, frame); py += kPacketRows)
                for (int px = x0; px < std::min(x0 + kTile, frame); px += kPacketColumns) {
                    f.packets.push_back(f.rays.size());
                    for (int y = py; y < std::min(py + kPacketRows, frame); ++y)
                        for (int i = px; i < std::min(px + kPacketColumns, frame); ++i)
                            f.rays.push_back(view.pixel_ray(i, frame - 1 - y));
                }
    f.packets.push_back(f.rays.size());
    return f;
}

void measure(const Input& input, int size, int frame, int rounds, bool classes, int instructions) {
    // Each side built on 1 and on 2 threads, alternately; the ray rows use the 1-thread builds
    // (the same trees: the lab's build is the same byte for byte on any thread count).
    std::unique_ptr<LabScene> lab_scene;
    std::unique_ptr<EmbreeScene> embree_scene;
    double lab_build[2], embree_build[2];
    for (int threads : {1, 2}) {
        auto l = std::make_unique<LabScene>(input.mesh, threads);
        auto e = std::make_unique<EmbreeScene>(input.mesh, threads);
        lab_build[threads - 1] = l->build_seconds;
        embree_build[threads - 1] = e->build_seconds;
        if (threads == 1) {
            lab_scene = std::move(l);
            embree_scene = std::move(e);
        }
    }
    const SurfaceList& list = lab_scene->list;
    const Accel& accel = *lab_scene->accel;
    const Mesh& mesh = std::get<Mesh>(list[0].shape);
    const std::size_t triangles = mesh.data().triangles.size();
    const double lab_bytes = double(accel.info().bytes + memory_bytes(mesh.data()));
    const EmbreeScene& embree = *embree_scene;

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
    std::printf("  memory per triangle: lab %.1f B (mesh + BVH), Embree %.1f B\n", lab_bytes / double(triangles),
                double(embree.bytes) / double(triangles));
    std::printf("  agreement: hit/miss %.4f %%, t within 1e-4 %.4f %% of common hits, shadow %.4f %%\n",
                100.0 * agree / double(primary.size()), both_hit ? 100.0 * t_agree / both_hit : 100.0,
                shadow.empty() ? 100.0 : 100.0 * shadow_agree / double(shadow.size()));
    // The builds: the lab's SAH (the mesh's tree, wide tree and blocks, and the scene's
    // structure) against Embree's high-quality build; the ratio is of speeds, as below.
    std::printf("  %-22s %7s %12s %12s %7s\n", "build", "threads", "lab s", "Embree s", "ratio");
    for (int threads : {1, 2})
        std::printf("  %-22s %7d %12.3f %12.3f %7.2f\n", "SAH build", threads, lab_build[threads - 1],
                    embree_build[threads - 1], embree_build[threads - 1] / lab_build[threads - 1]);
    if (instructions > 0) {
        std::vector<Ray> blocked, clear;
        for (const Ray& r : shadow) (occluded(mesh, r, Interval{0, 1}) ? blocked : clear).push_back(r);
        const auto lab_shadow = [&](const Ray& r) { return occluded(mesh, r, Interval{0, 1}); };
        const auto embree_shadow = [&](const Ray& r) { return embree.occluded(r, 1.0f); };
        count(input.name, "primary", "lab", primary, instructions, [&](const Ray& r) { return lab_primary(mesh, r); });
        count(input.name, "primary", "Embree", primary, instructions,
              [&](const Ray& r) { return std::isfinite(embree.hit(r, kFar)); });
        count(input.name, "shadow, blocked", "lab", blocked, instructions, lab_shadow);
        count(input.name, "shadow, blocked", "Embree", blocked, instructions, embree_shadow);
        count(input.name, "shadow, clear", "lab", clear, instructions, lab_shadow);
        count(input.name, "shadow, clear", "Embree", clear, instructions, embree_shadow);
        if (frame > 0) {
            // A whole render on one thread: everything a camera ray costs, search and all.
            const Scene scene = frame_scene(mesh, eye, centre);
            RenderOptions options;
            options.width = options.height = frame;
            options.antialiasing = scene.antialiasing;
            options.threads = 1;
            const FrameRays camera = frame_rays(scene, frame);
            count_batch(input.name, "whole frame", "lab", camera.rays.size(), instructions,
                        [&] { return long(render(scene, options).image.width); });
            count(input.name, "whole frame", "Embree", camera.rays, instructions,
                  [&](const Ray& r) { return std::isfinite(embree.hit(r, kFar)); });
            // The frame's search alone, packet by packet as the render makes it, against
            // Embree's own packets of the same rays.
            count_batch(input.name, "frame packets", "lab", camera.rays.size(), instructions, [&] {
                long n = 0;
                for (std::size_t k = 0; k < camera.packet_count(); ++k) {
                    HitRecord recs[kPacketRays];
                    n += std::popcount(scene.hit_packet(camera.packet(k), Interval{}, recs));
                }
                return n;
            });
            count_batch(input.name, "frame packets", "Embree", camera.rays.size(), instructions, [&] {
                long n = 0;
                for (std::size_t k = 0; k < camera.packet_count(); ++k) {
                    const std::span<const Ray> p = camera.packet(k);
                    n += embree.hit8(p.data(), int(p.size()));
                }
                return n;
            });
        }
        return;
    }
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
    const auto lab_hit = [&](const Ray& r) { return lab_primary(mesh, r); };
    const auto lab_occluded = [&](const Ray& r) { return occluded(mesh, r, Interval{0, 1}); };
    const auto embree_occluded = [&](const Ray& r) { return embree.occluded(r, 1.0f); };
    row("primary", primary, lab_hit, embree_primary);
    row("shadow", shadow, lab_occluded, embree_occluded);
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

    // The whole frame: a chapter program's render of the mesh shaded by its normals (one
    // camera ray per pixel, and all that a pixel costs besides its search: the ray made in
    // Real from the camera, the pixel's sampler, the HitRecord, the shading, the tiles, the
    // image), against Embree casting the same camera's rays one at a time, as the issue that
    // set the target asks. Embree's are made beforehand, in the render's order (tiles of
    // 16 x 16 pixels, handed out one at a time) and timed bare: what a user of Embree would
    // still have to add is on the lab's side only.
    if (frame <= 0) return;
    const Scene scene = frame_scene(mesh, eye, centre);
    RenderOptions options;
    options.width = options.height = frame;
    options.antialiasing = scene.antialiasing;
    const FrameRays camera = frame_rays(scene, frame);
    const std::size_t n_rays = camera.rays.size(), packets_per_tile = std::size_t(kTile * kTile / kPacketRays);
    // The same rays on both sides: as many pixels show the mesh as Embree's rays hit it.
    options.threads = 1;
    const Image image = render(scene, options).image;
    long shown = 0, embree_hits = 0;
    for (int y = 0; y < frame; ++y)
        for (int x = 0; x < frame; ++x) shown += image.at(x, y) != scene.background;
    for (const Ray& r : camera.rays) embree_hits += embree_primary(r);
    std::printf(
        "  whole frame: %dx%d, \"shading\": \"normal\", 1 sample per pixel; %ld pixels show the mesh, "
        "Embree hits it with %ld of the same rays\n",
        frame, frame, shown, embree_hits);
    // Mrays/s of one side's work over the frame's packets, a tile's packets at a time, on
    // `threads` threads, best of the rounds.
    const auto packets_timed = [&](int threads, auto&& packet) {
        return timed(
            threads, camera.packet_count(),
            [&](std::size_t b, std::size_t e) {
                long n = 0;
                for (std::size_t k = b; k < e; ++k) n += packet(camera.packet(k));
                sink += n;
            },
            packets_per_tile);
    };
    const auto lab_packet = [&](std::span<const Ray> p) {
        HitRecord recs[kPacketRays];
        return long(std::popcount(scene.hit_packet(p, Interval{}, recs)));
    };
    const auto embree_ones = [&](std::span<const Ray> p) {
        long n = 0;
        for (const Ray& r : p) n += embree_primary(r);
        return n;
    };
    const auto embree_eights = [&](std::span<const Ray> p) { return long(embree.hit8(p.data(), int(p.size()))); };
    const auto frame_row = [&](const char* name, auto&& lab_work, auto&& embree_work) {
        for (int threads : {1, 2}) {
            double lab = 1e30, emb = 1e30;
            for (int round = 0; round < rounds; ++round) {
                lab = std::min(lab, lab_work(threads));
                emb = std::min(emb, embree_work(threads));
            }
            const double lab_m = double(n_rays) / lab / 1e6, emb_m = double(n_rays) / emb / 1e6;
            std::printf("  %-22s %7d %12.2f %12.2f %7.2f\n", name, threads, lab_m, emb_m, lab_m / emb_m);
            std::fflush(stdout);
        }
    };
    // The frame's rays searched as the render searches them (Scene::hit_packet, packets of
    // 2 x 4 pixels, whole HitRecords), with nothing else around: the whole frame can be no
    // faster, so the gap between this row and the last is the render's own cost.
    frame_row(
        "frame rays, search", [&](int threads) { return packets_timed(threads, lab_packet); },
        [&](int threads) { return packets_timed(threads, embree_ones); });
    // The same packets against Embree's own packet search (rtcIntersect8, coherent rays): like
    // for like, for the reader who asks how the lab's packets compare with Embree's.
    frame_row(
        "frame rays, packets", [&](int threads) { return packets_timed(threads, lab_packet); },
        [&](int threads) { return packets_timed(threads, embree_eights); });
    frame_row(
        "whole frame",
        [&](int threads) {
            options.threads = threads;
            const auto start = Clock::now();
            sink += render(scene, options).image.width;
            return seconds_since(start);
        },
        [&](int threads) { return packets_timed(threads, embree_ones); });
}

}  // namespace

int main(int argc, char** argv) {
    int rounds = 5, size = 512, frame = 1024, instructions = 0;
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
            } else if (a == "--frame" && i + 1 < argc) {
                frame = std::max(0, std::atoi(argv[++i]));
            } else if (a == "--instructions" && i + 1 < argc) {
                instructions = std::max(1, std::atoi(argv[++i]));
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
                             "usage: bench_embree [--rounds N] [--size S] [--frame F] [--no-procedural] [--only TEXT] "
                             "[--by-class] [--instructions N] "
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
        "lab: Real=%s, fast path (two-level: 8-wide float BVH with 4-triangle blocks in each mesh, 8-wide over the "
        "surfaces); Embree %d.%d.%d, "
        "rtcIntersect1/rtcOccluded1\n",
        real_name(), RTC_VERSION_MAJOR, RTC_VERSION_MINOR, RTC_VERSION_PATCH);
    for (const Input& in : inputs)
        if (in.name.find(only) != std::string::npos) measure(in, size, frame, rounds, classes, instructions);
    return 0;
}
