// Boxes against spheres and ellipsoids as bounding volumes (book §10.8, the FAQ): how tight
// each is around the lab's own objects, what one ray test of each costs, and what the
// difference does to a hierarchy.
//
//   build/release/bin/bench_bounding_volumes [--lines N] SCENE.json|MESH.obj ...
//
// 1. Tightness. Around each object (a scene's meshes one by one, its spheres together; an OBJ
//    file whole) three bounds: the box, a bounding sphere (Ritter's, then the Badoiu-Clarkson
//    iteration, keeping the smaller: near the smallest, not exactly it) and an ellipsoid
//    (Khachiyan's minimum-volume one of the vertices, scaled out until every vertex is in).
//    N random lines (default 10^5) cross a ball that holds all three, uniformly in the
//    measure of lines (a uniform direction, then a uniform point of the disc across the ball),
//    the measure under which the chance of meeting a convex body is its surface area over
//    the ball's. Counted exactly: lines meeting the contents and each bound; "wasted" is the
//    share of a bound's lines that miss the contents, the work a bound lets through.
// 2. Cost. Nanoseconds per ray-bound test, 2^22 tests over 1,024 bounds that stay in cache:
//    the slab test (clip_to_box, 1/d given), the lab's stable sphere roots (exercise 2.2),
//    a bare sphere test (the discriminant and the far root, all a bound needs) and an
//    ellipsoid (the ray carried into the unit sphere's frame, then the bare test).
// 3. A hierarchy. The lab's SAH tree over a mesh's triangles (build_bvh, 4 per leaf), searched
//    for the closest hit once with each node's box and once with a sphere around the node's
//    triangles (Ritter's: the same topology, only the bound differs): nodes entered and
//    triangles tested per ray, exact counts, on the same lines; and both must find the same
//    hits.
#include "bounding_shapes.hpp"
#include "core/flat_bvh.hpp"
#include "geometry/mesh.hpp"
#include "geometry/sphere.hpp"
#include "io/obj.hpp"
#include "io/scene_file.hpp"

#include <pcg_random.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using namespace rt;
using namespace rt::bench;

namespace {

// An object: what a line may hit, and its vertices (a sphere: none; its ball is itself).
struct Object {
    std::string name;
    const Mesh* mesh = nullptr;
    std::vector<Sphere> spheres;
};

// Uniform random lines through a ball (see the top).
struct LineSource {
    pcg32 gen{2026};
    std::uniform_real_distribution<Real> u{0, 1};
    Ray next(const Ball& around) {
        const Real z = 2 * u(gen) - 1, phi = Real(6.283185307179586) * u(gen), s = std::sqrt(1 - z * z);
        const Vec3 d(s * std::cos(phi), s * std::sin(phi), z);
        const Vec3 a = std::abs(d.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
        const Vec3 e1 = glm::normalize(glm::cross(d, a)), e2 = glm::cross(d, e1);
        const Real rho = around.r * std::sqrt(u(gen)), psi = Real(6.283185307179586) * u(gen);
        const Vec3 o = around.c + rho * (std::cos(psi) * e1 + std::sin(psi) * e2) - 2 * around.r * d;
        return Ray{o, d};
    }
};

Real volume(const Box& b) {
    const Vec3 s = b.max - b.min;
    return s.x * s.y * s.z;
}

void tightness(const Object& obj, long lines) {
    struct Bounds {
        Box box;
        Ball ball;
        Ellipsoid ell;
    };
    std::vector<Bounds> bounds;  // one per sphere, or one for the mesh
    if (obj.mesh) {
        const std::vector<Vec3>& p = obj.mesh->data().positions;
        bounds.push_back({obj.mesh->box(), near_smallest_ball(p), min_ellipsoid(p)});
    } else {
        for (const Sphere& s : obj.spheres) {
            const glm::dmat3 m = glm::dmat3(1.0 / double(s.radius));
            bounds.push_back({bounding_box(s), Ball{s.center, s.radius}, Ellipsoid{m, s.center}});
        }
    }
    long hits[4] = {0, 0, 0, 0};  // contents, box, ball, ellipsoid
    double vol[3] = {0, 0, 0};
    LineSource source;
    const long per = std::max(1L, lines / long(bounds.size()));
    for (std::size_t k = 0; k < bounds.size(); ++k) {
        const Bounds& b = bounds[k];
        const Vec3 centre = (b.box.min + b.box.max) * Real(0.5);
        // The ellipsoid can reach past the ball (a flat object's does): its longest semi-axis is
        // at most the Frobenius norm of M^-1.
        const glm::dmat3 inv = glm::inverse(b.ell.m);
        const double axis = std::sqrt(glm::dot(inv[0], inv[0]) + glm::dot(inv[1], inv[1]) + glm::dot(inv[2], inv[2]));
        const Real reach = std::max({glm::length(b.box.max - centre), glm::length(b.ball.c - centre) + b.ball.r,
                                     glm::length(b.ell.c - centre) + Real(axis)});
        const Ball around{centre, reach * Real(1.01)};
        vol[0] += volume(b.box);
        vol[1] += 4.18879020478639 * b.ball.r * b.ball.r * b.ball.r;
        vol[2] += 4.18879020478639 / glm::determinant(b.ell.m);
        for (long l = 0; l < per; ++l) {
            const Ray ray = source.next(around);
            const Interval all{-kInfinity, kInfinity};
            bool contents;
            if (obj.mesh) {
                MeshHit h;
                contents = hit(*obj.mesh, ray, all, h);
            } else {
                Real t0, t1;
                contents = sphere_roots(ray, obj.spheres[k].center, obj.spheres[k].radius, t0, t1);
            }
            hits[0] += contents;
            hits[1] += might_hit(b.box, ray, all);
            hits[2] += hit_ball(b.ball.c, b.ball.r, ray.origin, ray.direction, -kInfinity, kInfinity);
            hits[3] += hit_ellipsoid(b.ell, ray, -kInfinity, kInfinity);
        }
    }
    auto wasted = [&](long h) { return h ? 100.0 * double(h - hits[0]) / double(h) : 0.0; };
    std::printf("%-24s %8zu %8ld %8ld %8ld %8ld %8ld %7.1f %7.1f %7.1f %7.2f %7.2f\n", obj.name.c_str(),
                obj.mesh ? obj.mesh->data().triangles.size() : obj.spheres.size(), per * long(bounds.size()), hits[0],
                hits[1], hits[2], hits[3], wasted(hits[1]), wasted(hits[2]), wasted(hits[3]), vol[1] / vol[0],
                vol[2] / vol[0]);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// 2. What one test costs.
void cost() {
    pcg32 gen(7);
    std::uniform_real_distribution<Real> u(-1, 1);
    constexpr int kBounds = 1024, kRays = 4096;
    std::vector<Box> boxes(kBounds);
    std::vector<Ball> balls(kBounds);
    std::vector<Ellipsoid> ells(kBounds);
    for (int k = 0; k < kBounds; ++k) {
        const Vec3 c(u(gen), u(gen), u(gen)), h(0.3 + 0.2 * u(gen), 0.3 + 0.2 * u(gen), 0.3 + 0.2 * u(gen));
        boxes[k] = Box{c - h, c + h};
        balls[k] = Ball{c, glm::length(h)};
        // The ellipsoid through the box's corners, turned by an angle: a general 3 x 3 matrix.
        glm::dmat3 scale(0.0);
        for (int a = 0; a < 3; ++a) scale[a][a] = 1.0 / (double(h[a]) * 1.7320508075688772);
        const double a = 3 * double(u(gen)), ca = std::cos(a), sa = std::sin(a);
        ells[k] = Ellipsoid{scale * glm::dmat3(ca, sa, 0, -sa, ca, 0, 0, 0, 1), c};
    }
    std::vector<Ray> rays(kRays);
    std::vector<Vec3> inv(kRays);
    for (int k = 0; k < kRays; ++k) {
        rays[k] = Ray{Vec3(u(gen), u(gen), 4), Vec3(0.3 * u(gen), 0.3 * u(gen), -1)};
        inv[k] = Real(1) / rays[k].direction;
    }
    const long tests = long(kRays) * kBounds;
    auto time = [&](auto&& test) {
        double best = 1e30;
        long count = 0;
        for (int round = 0; round < 5; ++round) {
            count = 0;
            const auto start = std::chrono::steady_clock::now();
            for (int r = 0; r < kRays; ++r)
                for (int b = 0; b < kBounds; ++b) count += test(r, b);
            best = std::min(best, seconds_since(start));
        }
        return std::pair{best / double(tests) * 1e9, count};
    };
    const Interval iv{0, 100};
    const auto slab = time([&](int r, int b) { return might_hit(boxes[b], rays[r], inv[r], iv); });
    const auto roots = time([&](int r, int b) {
        Real t0, t1;
        return sphere_roots(rays[r], balls[b].c, balls[b].r, t0, t1) && t1 >= iv.min && t0 <= iv.max;
    });
    const auto bare = time([&](int r, int b) {
        return hit_ball(balls[b].c, balls[b].r, rays[r].origin, rays[r].direction, iv.min, iv.max);
    });
    const auto ell = time([&](int r, int b) { return hit_ellipsoid(ells[b], rays[r], iv.min, iv.max); });
    std::printf("\ncost of one test, %ld tests (fastest of 5 rounds; 1,024 bounds in cache):\n", tests);
    std::printf("  %-44s %8s %8s %10s\n", "test", "ns", "vs slab", "hits");
    std::printf("  %-44s %8.2f %8.2f %10ld\n", "box: slab test (clip_to_box, 1/d given)", slab.first, 1.0, slab.second);
    std::printf("  %-44s %8.2f %8.2f %10ld\n", "sphere: the lab's stable roots (ex. 2.2)", roots.first,
                roots.first / slab.first, roots.second);
    std::printf("  %-44s %8.2f %8.2f %10ld\n", "sphere: discriminant and far root only", bare.first,
                bare.first / slab.first, bare.second);
    std::printf("  %-44s %8.2f %8.2f %10ld\n", "ellipsoid: ray to unit sphere, then as above", ell.first,
                ell.first / slab.first, ell.second);
}

// 3. One tree, two kinds of bound.
struct Counts {
    long nodes = 0, triangles = 0, hits = 0;
};

template <class Enter>
Real closest(const FlatBvh& bvh, const Mesh& mesh, const Ray& ray, Enter enter, Counts& n) {
    const MeshData& d = mesh.data();
    Real best = kInfinity;
    std::uint32_t stack[2 * kMaxBvhDepth + 2];
    int top = 0;
    stack[top++] = 0;
    while (top) {
        const std::uint32_t k = stack[--top];
        ++n.nodes;
        const Real t = enter(k, ray, best);  // +inf: missed
        if (t == kInfinity || t > best) continue;
        const BvhNode& node = bvh.nodes[k];
        if (!node.leaf()) {
            stack[top++] = node.first + 1;
            stack[top++] = node.first;
            continue;
        }
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
            const auto& t = d.triangles[bvh.items[i]];
            TriangleHit h;
            ++n.triangles;
            if (ray_triangle_watertight(ray, d.positions[t[0]], d.positions[t[1]], d.positions[t[2]], Interval{0, best},
                                        h))
                best = h.t;
        }
    }
    n.hits += best < kInfinity;
    return best;
}

// Every triangle's vertices below node k, appended to `out`.
void gather(const FlatBvh& bvh, const MeshData& d, std::uint32_t k, std::vector<Vec3>& out) {
    const BvhNode& node = bvh.nodes[k];
    if (!node.leaf()) {
        gather(bvh, d, node.first, out);
        gather(bvh, d, node.first + 1, out);
        return;
    }
    for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
        for (std::uint32_t v : d.triangles[bvh.items[i]]) out.push_back(d.positions[v]);
}

// Returns how many lines found a different closest hit with spheres.
long hierarchy(const Object& obj, long lines) {
    const Mesh& mesh = *obj.mesh;
    const MeshData& d = mesh.data();
    std::vector<Box> boxes;
    for (const auto& t : d.triangles) {
        Box b;
        for (std::uint32_t v : t) b.expand(d.positions[v]);
        boxes.push_back(b);
    }
    const FlatBvh bvh = build_bvh(boxes, 4);
    std::vector<Ball> balls(bvh.nodes.size());
    double box_area = 0, ball_area = 0;
    for (std::uint32_t k = 0; k < bvh.nodes.size(); ++k) {
        std::vector<Vec3> p;
        gather(bvh, d, k, p);
        balls[k] = ritter(p);
        const BvhNode& n = bvh.nodes[k];
        const double x = n.hi[0] - n.lo[0], y = n.hi[1] - n.lo[1], z = n.hi[2] - n.lo[2];
        box_area += 2 * (x * y + y * z + z * x);
        ball_area += 4 * 3.141592653589793 * double(balls[k].r) * double(balls[k].r);
    }
    const Box root = mesh.box();
    const Vec3 centre = (root.min + root.max) * Real(0.5);
    const Ball around{centre, std::max(glm::length(root.max - centre), glm::length(balls[0].c - centre) + balls[0].r)};
    LineSource source;
    std::vector<Ray> rays;
    for (long l = 0; l < lines; ++l) rays.push_back(source.next(around));
    Counts with_box, with_ball;
    long differ = 0;
    double box_s = 0, ball_s = 0;
    for (int pass = 0; pass < 2; ++pass) {
        with_box = with_ball = {};
        const auto start = std::chrono::steady_clock::now();
        std::vector<Real> tb(rays.size());
        for (std::size_t r = 0; r < rays.size(); ++r) {
            const BoxRay br(rays[r]);
            tb[r] = closest(
                bvh, mesh, rays[r],
                [&](std::uint32_t k, const Ray&, Real hi) { return enter(bvh.nodes[k], br, 0, hi); }, with_box);
        }
        box_s = seconds_since(start);
        const auto start2 = std::chrono::steady_clock::now();
        for (std::size_t r = 0; r < rays.size(); ++r) {
            const Real t = closest(
                bvh, mesh, rays[r],
                [&](std::uint32_t k, const Ray& ray, Real hi) { return enter_ball(balls[k], ray, hi); }, with_ball);
            if (pass == 1 && t != tb[r]) ++differ;
        }
        ball_s = seconds_since(start2);
    }
    const double n = double(rays.size());
    std::printf("%-24s %8zu %6zu %8ld %8ld %9.2f %9.2f %9.2f %9.2f %7.2f %7.2f %6ld\n", obj.name.c_str(),
                d.triangles.size(), bvh.nodes.size(), long(rays.size()), with_box.hits, double(with_box.nodes) / n,
                double(with_ball.nodes) / n, double(with_box.triangles) / n, double(with_ball.triangles) / n,
                ball_area / box_area, ball_s / box_s, differ);
    return differ;
}

}  // namespace

int main(int argc, char** argv) {
    long lines = 100000;
    std::vector<std::string> inputs;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--lines" && i + 1 < argc) {
            lines = std::atol(argv[++i]);
            if (lines < 100) {
                std::fprintf(stderr, "bench_bounding_volumes: --lines must be at least 100\n");
                return 2;
            }
        } else if (a.size() > 5 && (a.ends_with(".json") || a.ends_with(".obj"))) {
            inputs.push_back(a);
        } else {
            std::fprintf(stderr, "usage: bench_bounding_volumes [--lines N] SCENE.json|MESH.obj ...\n");
            return 2;
        }
    }
    if (inputs.empty()) {
        std::fprintf(stderr, "bench_bounding_volumes: no scene or mesh given\n");
        return 2;
    }
    std::vector<Scene> scenes;  // they own the meshes the objects point at
    std::vector<Mesh> files;
    scenes.reserve(inputs.size());
    files.reserve(inputs.size());
    std::vector<Object> objects;
    try {
        for (const std::string& in : inputs) {
            const std::string stem = in.substr(in.find_last_of('/') + 1);
            if (in.ends_with(".obj")) {
                files.emplace_back(load_obj(in));
                objects.push_back({stem, &files.back(), {}});
                continue;
            }
            scenes.push_back(load_scene_file(in));
            const SurfaceList& list = scenes.back().surfaces;
            Object spheres{stem + ": spheres", nullptr, {}};
            for (SurfaceId k = 0; k < list.size(); ++k) {
                if (const Mesh* m = std::get_if<Mesh>(&list[k].shape))
                    objects.push_back({stem + ": " + list.name(k), m, {}});
                else if (const Sphere* s = std::get_if<Sphere>(&list[k].shape))
                    spheres.spheres.push_back(*s);
            }
            if (!spheres.spheres.empty()) objects.push_back(std::move(spheres));
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_bounding_volumes: %s\n", e.what());
        return 2;
    }

    std::printf(
        "Real=%s. 1. Tightness: %ld random lines per row through a ball around the object (uniform in\n"
        "the measure of lines); how many meet the contents and each bound, the share of each bound's\n"
        "lines that miss the contents, and each bound's volume over the box's.\n",
        real_name(), lines);
    std::printf("%-24s %8s %8s %8s %8s %8s %8s %7s %7s %7s %7s %7s\n", "object", "prims", "lines", "contents", "box",
                "sphere", "ellips.", "box %", "sph. %", "ell. %", "V s/b", "V e/b");
    for (const Object& o : objects) {
        tightness(o, lines);
        std::fflush(stdout);
    }

    cost();

    std::printf(
        "\n3. One SAH tree (4 triangles a leaf), its nodes bounded by boxes or by spheres round the same\n"
        "triangles; the closest hit of %ld lines as above: nodes entered and triangles tested per line,\n"
        "the spheres' summed area over the boxes', time with spheres over time with boxes, and lines\n"
        "whose hit differs (must be 0).\n",
        lines);
    std::printf("%-24s %8s %6s %8s %8s %9s %9s %9s %9s %7s %7s %6s\n", "mesh", "tris", "nodes", "lines", "hits",
                "nodes/box", "nodes/sph", "tris/box", "tris/sph", "A s/b", "t s/b", "differ");
    long differ = 0;
    for (const Object& o : objects)
        if (o.mesh && o.mesh->data().triangles.size() >= 1000) differ += hierarchy(o, lines);
    if (differ) {
        std::fprintf(stderr, "bench_bounding_volumes: %ld lines found another hit through spheres\n", differ);
        return 1;
    }
    return 0;
}
