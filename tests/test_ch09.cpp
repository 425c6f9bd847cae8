// Chapter 09: instancing (course §9.8): rays into object space, normals by the inverse
// transpose, transformed boxes, and instances that agree with explicitly transformed
// geometry, mirror images and near-singular scales included.
#include "geometry/procedural.hpp"
#include "geometry/shape.hpp"
#include "geometry/sphere.hpp"
#include "io/scene_file.hpp"
#include "support.hpp"
#include "support/big_ground.hpp"
#include "support/source_dir.hpp"

#include <pcg_random.hpp>

#include <cmath>
#include <memory>
#include <random>

using namespace rt;

namespace {

const std::string kScenes = rt::test::source_dir() + "/chapters/ch09_instancing/scenes/";

// The course's example: scale (2, 1, 1), rotate 45 degrees about z, move 1 along x.
Affine course_ellipse() {
    return Affine::scale(Vec3(2, 1, 1)).then(Affine::rotate(Vec3(0, 0, 1), 45)).then(Affine::translate(Vec3(1, 0, 0)));
}

// The mesh with every vertex transformed; a mirroring transform also reverses each
// triangle's winding, so that the geometric normals still point out.
MeshData transformed(MeshData data, const Affine& a) {
    for (Vec3& p : data.positions) p = a.point(p);
    if (glm::determinant(a.m) < 0)
        for (auto& t : data.triangles) std::swap(t[1], t[2]);
    return data;
}

}  // namespace

TEST_SUITE("ch09") {
TEST_CASE("9.1 object_ray: points take the whole inverse, directions only its matrix, and t carries over") {
    const Affine to_world = course_ellipse();
    const Affine to_object = inverse(to_world);
    const Ray r{Vec3(3, 2, 1), Vec3(-1, 0.5, 2), Real(0.25)};
    const Ray o = object_ray(to_object, r);
    CHECK(o.time == Real(0.25));
    for (const Real t : {Real(0), Real(0.5), Real(3)}) {
        const Vec3 back = to_world.point(o.at(t));
        CHECK(back.x == doctest::Approx(r.at(t).x));
        CHECK(back.y == doctest::Approx(r.at(t).y));
        CHECK(back.z == doctest::Approx(r.at(t).z));
    }
    // A pure translation moves the origin and leaves the direction alone.
    const Ray moved = object_ray(inverse(Affine::translate(Vec3(1, 2, 3))), r);
    CHECK(moved.origin == Vec3(2, 0, -2));
    CHECK(moved.direction == r.direction);
}

TEST_CASE("9.1 an instance 10^6 from the origin: the direction carries none of the translation's rounding") {
    // M^-1 d does not depend on the translation, so it keeps its digits however far the
    // instance is (8 epsilons of |M^-1| |d|). Taken as M^-1 (e + d) - M^-1 e, both points carry
    // the translation and the difference keeps only what 10^6 leaves of them.
    const Affine to_world = Affine::scale(Vec3(2, 0.5, 1))
                                .then(Affine::rotate(Vec3(1, 2, 3), 40))
                                .then(Affine::translate(Vec3(1e6, -2e6, 3e6)));
    const Affine to_object = inverse(to_world);
    for (const Vec3 d : {Vec3(-1, 0.5, 2), Vec3(0.001, -0.002, 0.0015), Vec3(300, 100, -200)}) {
        const Ray r{Vec3(1e6 + 3, -2e6 + 1, 3e6 - 2), d, Real(0.5)};
        const Ray o = object_ray(to_object, r);
        CAPTURE(d);
        CAPTURE(o.direction);
        const Vec3 want = to_object.vector(d);
        const Real size =
            glm::length(glm::abs(to_object.m[0]) * std::abs(d.x) + glm::abs(to_object.m[1]) * std::abs(d.y) +
                        glm::abs(to_object.m[2]) * std::abs(d.z));
        CHECK(glm::length(o.direction - want) <= 8 * test::kEps * size);
        const Vec3 origin = to_object.point(r.origin);
        CHECK(glm::length(o.origin - origin) <= 8 * test::kEps * (glm::length(to_object.t) + glm::length(origin)));
        CHECK(o.time == Real(0.5));
    }
}

TEST_CASE("9.2 world_normal: the inverse transpose keeps normals perpendicular (the ellipsoid's gradient)") {
    // The course's ellipsoid: world point q = M p for p on the unit sphere. Its outward
    // normal is the gradient of |M^-1 (q - t)|^2, proportional to M^-T M^-1 (q - t).
    const Affine to_world = course_ellipse(), to_object = inverse(to_world);
    pcg32 rng(9);
    std::uniform_real_distribution<double> u(-1, 1);
    int failures = 0;
    for (int k = 0; k < 500; ++k) {
        const Vec3 p = unit_vector(Vec3{Real(u(rng)), Real(u(rng)), Real(u(rng))});
        const Vec3 got = world_normal(to_object, p);  // the unit sphere's normal at p is p
        const Vec3 want = unit_vector(glm::transpose(to_object.m) * (to_object.m * (to_world.point(p) - to_world.t)));
        RT_CHECK_FIRST(failures, glm::length(got - want) <= 64 * test::kEps);
        RT_CHECK_FIRST(failures, std::abs(glm::length(got) - 1) <= 8 * test::kEps);
        // Perpendicular to a tangent of the surface: M times a tangent of the sphere.
        const Vec3 tangent = to_world.vector(glm::cross(p, Vec3(0.3, 0.5, 0.8)));
        RT_CHECK_FIRST(failures, std::abs(glm::dot(got, tangent)) <= 64 * test::kEps * glm::length(tangent));
    }
    CHECK(failures == 0);
    // A plain scale: the normal of x = 1 on a box scaled by (2, 1, 1) still points along x.
    CHECK(world_normal(inverse(Affine::scale(Vec3(2, 1, 1))), Vec3(1, 0, 0)) == Vec3(1, 0, 0));
}

TEST_CASE("9.2 mirrors and near-flat scales: the normal stays unit, square to the surface, and outward") {
    // The unit sphere stretched into an ellipsoid by each transform: at the world point q = M p
    // + t its outward normal is M^-T p, made unit. A mirror (det M < 0) reverses a mesh's
    // winding, not this normal: it still points away from the centre t. A scale of 1e-4
    // flattens the sphere to a disk whose normals nearly all point along the flat axis.
    const Affine cases[] = {
        Affine::scale(Vec3(-1, 1, 1)).then(Affine::translate(Vec3(0, 2, 0))),        // a mirror image
        Affine::scale(Vec3(1.5, -0.5, 2)).then(Affine::rotate(Vec3(0, 1, 0), 30)),   // another, stretched
        Affine::scale(Vec3(-2, -1, -0.5)).then(Affine::rotate(Vec3(1, -1, 2), 75)),  // turned inside out
        Affine::scale(Vec3(1, 1e-4, 1)).then(Affine::rotate(Vec3(1, 0, 1), 20)),     // nearly flat
    };
    pcg32 rng(17);
    std::uniform_real_distribution<double> u(-1, 1);
    for (std::size_t c = 0; c < std::size(cases); ++c) {
        const Affine& to_world = cases[c];
        const Affine to_object = inverse(to_world);
        int failures = 0;
        for (int k = 0; k < 300; ++k) {
            const Vec3 p = unit_vector(Vec3{Real(u(rng)), Real(u(rng)), Real(u(rng))});
            const Vec3 got = world_normal(to_object, p);  // the unit sphere's normal at p is p
            const Vec3 want = unit_vector(glm::transpose(to_object.m) * p);
            const Vec3 outward = to_world.vector(p);  // q - t: from the centre to the point
            const Vec3 tangent = to_world.vector(glm::cross(p, Vec3(0.3, 0.5, 0.8)));
            CAPTURE(c);
            CAPTURE(p);
            CAPTURE(got);
            CAPTURE(want);
            RT_CHECK_FIRST(failures, glm::length(got - want) <= 64 * test::kEps);
            RT_CHECK_FIRST(failures, std::abs(glm::length(got) - 1) <= 8 * test::kEps);
            RT_CHECK_FIRST(failures, glm::dot(got, outward) > 0);
            RT_CHECK_FIRST(failures, std::abs(glm::dot(got, tangent)) <= 64 * test::kEps * glm::length(tangent));
        }
        CHECK(failures == 0);
    }
}

TEST_CASE("9.3 every corner is needed: turns that make each corner alone the farthest along x") {
    // For corner k of the box, the turn that takes the corner's offset from the centre to +x
    // makes that corner the only one at the box's greatest x: a box that forgets it comes out
    // short there. (A turn about a coordinate axis shares each extreme between two corners and
    // cannot tell.) Each face against the box of the corners worked out in long double, within
    // 8 epsilons of the size of what it sums.
    const Box box{Vec3(1, -2, 0.5), Vec3(3, 1, 1.5)};
    const Vec3 centre = (box.min + box.max) / Real(2), half = (box.max - box.min) / Real(2);
    for (int k = 0; k < 8; ++k) {
        const Vec3 offset(k & 1 ? half.x : -half.x, k & 2 ? half.y : -half.y, k & 4 ? half.z : -half.z);
        const Vec3 along = glm::normalize(offset);
        const Real degrees = glm::degrees(std::acos(along.x));
        const Affine to_world =
            Affine::rotate(glm::cross(along, Vec3(1, 0, 0)), degrees).then(Affine::translate(Vec3(5, -6, 7)));
        const Box got = transform_box(to_world, box);
        CAPTURE(k);
        CAPTURE(got);
        for (int i = 0; i < 3; ++i) {
            long double low = to_world.t[i], high = to_world.t[i], size = std::abs(to_world.t[i]);
            for (int j = 0; j < 3; ++j) {
                const long double m = to_world.m[j][i], a = m * box.min[j], b = m * box.max[j];
                low += std::min(a, b);
                high += std::max(a, b);
                size += std::abs(m) * std::max(std::abs(box.min[j]), std::abs(box.max[j]));
            }
            CAPTURE(i);
            CHECK(std::abs(got.min[i] - low) <= 8 * test::kEps * size);
            CHECK(std::abs(got.max[i] - high) <= 8 * test::kEps * size);
        }
        // The corner itself reaches the greatest x: |offset| past the centre's image.
        CHECK(got.max.x == doctest::Approx(to_world.point(centre).x + glm::length(offset)).epsilon(1e-6));
    }
}

TEST_CASE("9.3 transform_box: the box of the eight transformed corners") {
    const Box unit{Vec3(-1), Vec3(1)};
    const Box turned = transform_box(Affine::rotate(Vec3(0, 0, 1), 45), unit);
    CHECK(turned.max.x == doctest::Approx(std::sqrt(2.0)));
    CHECK(turned.min.y == doctest::Approx(-std::sqrt(2.0)));
    CHECK(turned.max.z == doctest::Approx(1));
    const Box moved = transform_box(Affine::scale(Vec3(2, -3, 1)).then(Affine::translate(Vec3(5, 0, 0))), unit);
    CHECK(moved.min == Vec3(3, -3, -1));
    CHECK(moved.max == Vec3(7, 3, 1));
    // It contains the transformed shape: every point of the course's ellipsoid.
    const Instance ellipsoid(std::make_shared<const Shape>(Sphere(Vec3(0), 1)), course_ellipse());
    pcg32 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int k = 0; k < 200; ++k) {
        const Vec3 q = course_ellipse().point(unit_vector(Vec3{Real(u(rng)), Real(u(rng)), Real(u(rng))}));
        CHECK(glm::all(glm::lessThanEqual(ellipsoid.box().min, q + Vec3(1e-5))));
        CHECK(glm::all(glm::greaterThanEqual(ellipsoid.box().max, q - Vec3(1e-5))));
    }
}

TEST_CASE("analytic: an axial ray through the course's ellipsoid meets it where the quadric says") {
    // Rays along -z through (x, y): the ellipsoid is |M^-1 (q - t)| = 1; with the rotation R
    // by 45 degrees and S = diag(2, 1, 1), M^-1 (q - t) = S^-1 R^T (q - t), so
    //   ((x' / 2)^2 + y'^2 + z^2 = 1) with (x', y') = R^T (x - 1, y),
    // and z = sqrt(1 - (x'/2)^2 - y'^2): the first hit from z = 10 is at t = 10 - z.
    const Instance e(std::make_shared<const Shape>(Sphere(Vec3(0), 1)), course_ellipse());
    const Real c = std::sqrt(Real(0.5));
    for (const Vec2 xy : {Vec2(1, 0), Vec2(1.8, 0.6), Vec2(0.2, -0.5), Vec2(2.2, 1.1)}) {
        const Real xp = c * (xy.x - 1) + c * xy.y, yp = -c * (xy.x - 1) + c * xy.y;
        const Real inside = 1 - (xp / 2) * (xp / 2) - yp * yp;
        HitRecord rec;
        const bool hit = hit_record(e, Ray{Vec3(xy.x, xy.y, 10), Vec3(0, 0, -1)}, Interval{}, SurfaceRef{}, rec);
        CAPTURE(xy);
        REQUIRE(hit == (inside > 0));
        if (hit) CHECK(rec.t == doctest::Approx(10 - std::sqrt(inside)));
    }
}

TEST_CASE("9.1 instances hit where the explicitly transformed mesh does: t, point, normal, mirrors included") {
    const MeshData base = icosphere(Vec3(0.1, -0.2, 0.3), 1, 2);
    const auto shared = std::make_shared<const Shape>(Mesh(base));
    const Affine cases[] = {
        course_ellipse(),
        Affine::rotate(Vec3(1, 2, 3), 70).then(Affine::translate(Vec3(-3, 1, 2))),
        Affine::scale(Vec3(-1, 1, 1)).then(Affine::translate(Vec3(0, 2, 0))),       // a mirror image
        Affine::scale(Vec3(1.5, -0.5, 2)).then(Affine::rotate(Vec3(0, 1, 0), 30)),  // another
        Affine::scale(Vec3(1, 1e-4, 1)).then(Affine::rotate(Vec3(1, 0, 1), 20)),    // nearly flat
    };
    pcg32 rng(99);
    std::uniform_real_distribution<double> u(-1, 1);
    for (std::size_t c = 0; c < std::size(cases); ++c) {
        CAPTURE(c);
        const Instance instance(shared, cases[c]);
        const Mesh explicit_mesh(transformed(base, cases[c]));
        const Box box = explicit_mesh.box();
        const Vec3 mid = (box.min + box.max) / Real(2), half = (box.max - box.min) / Real(2) + Vec3(Real(0.01));
        int both = 0, disagree = 0, failures = 0;
        for (int k = 0; k < 4000; ++k) {
            const Vec3 origin =
                mid + Real(3) * glm::length(half) * unit_vector(Vec3{Real(u(rng)), Real(u(rng)), Real(u(rng))});
            const Vec3 target = mid + half * Vec3{Real(u(rng)), Real(u(rng)), Real(u(rng))} * Real(0.9);
            const Ray ray{origin, target - origin};
            HitRecord a, b;
            const bool ha = hit_record(instance, ray, Interval{}, SurfaceRef{}, a);
            const bool hb = hit_record(explicit_mesh, ray, Interval{}, SurfaceRef{}, b);
            if (ha != hb) {
                ++disagree;  // only where the ray grazes an edge, computed in two spaces
                continue;
            }
            if (!ha) continue;
            ++both;
            const Real scale = glm::length(ray.direction);
            RT_CHECK_FIRST(failures, std::abs(a.t - b.t) * scale <= 1e3 * test::kEps * glm::length(origin));
            RT_CHECK_FIRST(failures, glm::length(a.p - b.p) <= 1e3 * test::kEps * glm::length(origin));
            if (a.primitive == b.primitive) RT_CHECK_FIRST(failures, glm::dot(a.normal, b.normal) >= 1 - Real(1e-3));
        }
        CHECK(both > 2000);
        CHECK(disagree <= 4);
        CHECK(failures == 0);
    }
}

TEST_CASE("instances carry a sphere's error bound into the world: no acne on a ground scaled up or down") {
    // A ground sphere of radius R = 10^3 to 10^5 centred R below the origin (the big ground
    // of book §6.3), made by an instance from a unit sphere scaled up and from one 100 R
    // across scaled down. The world record's bound is the object's times the scale, plus the
    // transform's rounding: about the bound of the same sphere built in the world. Left in
    // object space, it would be R times too small (acne) or 100 times too large (a gap any
    // occluder that close slips through).
    for (int e = 3; e <= 5; ++e) {
        const Real radius = Real(std::pow(10.0, e));
        const Real world_bound = sphere_error(Sphere(Vec3(0, -radius, 0), radius));
        for (const Real object_radius : {Real(1), 100 * radius}) {
            CAPTURE(radius);
            CAPTURE(object_radius);
            const Sphere object(Vec3(0, -object_radius, 0), object_radius);
            Scene scene;
            scene.surfaces.add(
                Instance(std::make_shared<const Shape>(object), Affine::scale(Vec3(radius / object_radius))), 0,
                "ground");
            Real least = kInfinity, most = 0;
            const test::SelfShadow count = test::self_shadow(scene, [&](const HitRecord& rec) {
                least = std::min(least, rec.error);
                most = std::max(most, rec.error);
                return rec.error;
            });
            CHECK(count.rays > 13000);
            CHECK(count.acne == 0);
            CHECK(least >= world_bound);
            CHECK(most <= Real(1.1) * world_bound);
        }
    }
}

TEST_CASE("9.1 instances of one mesh share it: the instances scene stores its triangles once") {
    SceneSummary summary;
    const Scene scene = load_scene_file(kScenes + "instances.json", &summary);
    CHECK(summary.instances == 25);
    const auto* first = std::get_if<Instance>(&scene.surfaces[1].shape);
    REQUIRE(first);
    const auto* mesh = std::get_if<Mesh>(&first->base());
    REQUIRE(mesh);
    CHECK(mesh->smooth());
    CHECK(summary.shared_bytes == 24 * memory_bytes(first->base()));
    for (SurfaceId s = 2; s < scene.surfaces.size(); ++s)
        CHECK(&std::get<Instance>(scene.surfaces[s].shape).base() == &first->base());
    // Different materials on the same mesh.
    CHECK(scene.surfaces[1].material != scene.surfaces[2].material);
    // And the scene renders what its surfaces say: the ray through an instance's centre
    // hits that instance, at the distance the transform gives.
    const Affine& to_world = first->to_world();
    const Vec3 centre = to_world.point(Vec3(0));
    const Ray r{centre + Vec3(0, 10, 0), Vec3(0, -1, 0)};
    HitRecord rec;
    REQUIRE(scene.hit(r, Interval{}, rec));
    CHECK(rec.surface == 1);
    CHECK(rec.t == doctest::Approx(10 - to_world.m[1][1]).epsilon(0.02));  // y scale; the mesh is a polyhedron
}
}
