// The shared library: images, sampling, the render loop.
#include "core/flat_bvh.hpp"
#include "core/float_round.hpp"
#include "core/names.hpp"
#include "geometry/mesh.hpp"
#include "geometry/procedural.hpp"
#include "geometry/sphere.hpp"
#include "io/image_file.hpp"
#include "render/camera.hpp"
#include "render/integrators.hpp"
#include "render/render.hpp"
#include "shading/light.hpp"
#include "support.hpp"

#include <unistd.h>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <pcg_random.hpp>
#include <vector>

using namespace rt;
namespace fs = std::filesystem;

namespace {

fs::path temp_dir() {
    const fs::path p = fs::temp_directory_path() / ("rtlab-test-" + std::to_string(::getpid()));
    fs::create_directories(p);
    return p;
}

Image gradient(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) img.at(x, y) = Color(float(x) / float(w - 1), float(y) / float(h - 1), 0.25f);
    return img;
}

// A scene whose pixels depend on their random samples: spp > 1 jitters the rays over the
// sphere's silhouette.
Scene jittered_scene() {
    Scene s;
    s.camera.eye = Vec3(0);
    s.camera.target = Vec3(0, 0, -1);
    s.surfaces.add(Sphere(Vec3(0.2, 0.1, -3), 1), 0, "s");
    s.integrator = std::make_shared<NormalIntegrator>();
    return s;
}

bool same_bits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::equal(a.pixels.begin(), a.pixels.end(), b.pixels.begin(),
                      [](const Color& x, const Color& y) { return x.r == y.r && x.g == y.g && x.b == y.b; });
}

}  // namespace

TEST_SUITE("common") {
TEST_CASE("bounding_box of a sphere (course §9.4.1)") {
    const Box b = bounding_box(Sphere(Vec3(1, 2, 3), 2));
    CHECK(b.min == Vec3(-1, 0, 1));
    CHECK(b.max == Vec3(3, 4, 5));
    CHECK_THROWS_AS(Sphere(Vec3(0), 0), std::invalid_argument);
    CHECK_THROWS_AS(Sphere(Vec3(0), std::nan("")), std::invalid_argument);
    CHECK_THROWS_AS(Sphere(Vec3(0, kInfinity, 0), 1), std::invalid_argument);
}

TEST_CASE("lights report direction, distance and colour") {
    Light point;
    point.position = Vec3(3, 4, 0);
    point.color = Color(0.5f);
    const LightSample s = point.sample(Vec3(0));
    CHECK(s.distance == doctest::Approx(5));
    CHECK(s.direction.x == doctest::Approx(0.6));
    CHECK(s.direction.y == doctest::Approx(0.8));
    CHECK(s.color == Color(0.5f));
    Light sun;
    sun.type = Light::Type::directional;
    sun.direction = Vec3(0, -2, 0);
    const LightSample d = sun.sample(Vec3(7, 8, 9));
    CHECK(d.distance == kInfinity);
    CHECK(d.direction == Vec3(0, 1, 0));
}

TEST_CASE("View: degenerate cameras are rejected with a clear error") {
    Camera cam;
    cam.up = Vec3(0, 0, 1);  // parallel to the view direction (0, 0, -1)
    CHECK_THROWS_WITH_AS(cam.view(10, 10), "camera: up is parallel to the view direction", std::invalid_argument);
    cam.up = Vec3(0, 1, 0);
    cam.target = cam.eye;
    CHECK_THROWS_AS(cam.view(10, 10), std::invalid_argument);
    cam.target = Vec3(0, 0, -1);
    cam.vertical_fov_degrees = 180;
    CHECK_THROWS_AS(cam.view(10, 10), std::invalid_argument);
}

TEST_CASE("sRGB transfer function: known values and round trip") {
    CHECK(linear_to_srgb(0) == 0);
    CHECK(linear_to_srgb(1) == doctest::Approx(1));
    CHECK(linear_to_srgb(0.5f) == doctest::Approx(0.735357f).epsilon(1e-5));
    CHECK(linear_to_srgb(0.002f) == doctest::Approx(0.02584f).epsilon(1e-4));  // the linear toe
    CHECK(linear_to_srgb(-3) == 0);                                            // clamped
    CHECK(linear_to_srgb(7) == doctest::Approx(1));
    for (int i = 0; i <= 255; ++i) CHECK(std::lround(255 * linear_to_srgb(srgb_to_linear(float(i) / 255))) == i);
}

TEST_CASE("sRGB 8-bit codes from the threshold table equal the formula's") {
    const auto formula = [](float x) { return int(std::lround(255.0f * linear_to_srgb(x))); };
    // Every float of [0, 1] in steps of 4099 bit patterns, then every float within 2000 ulps
    // of each place where the code steps up: the places the table must get exactly.
    const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
    long checked = 0, wrong = 0;
    for (std::uint32_t bits = 0; bits <= one; bits += 4099, ++checked)
        wrong += linear_to_srgb8(std::bit_cast<float>(bits)) != formula(std::bit_cast<float>(bits));
    for (int k = 1; k <= 255; ++k) {
        const float at = srgb_to_linear((float(k) - 0.5f) / 255);  // near the step to code k
        const std::uint32_t centre = std::bit_cast<std::uint32_t>(at);
        for (std::uint32_t bits = centre - 2000; bits <= centre + 2000; ++bits, ++checked)
            wrong += linear_to_srgb8(std::bit_cast<float>(bits)) != formula(std::bit_cast<float>(bits));
    }
    CHECK(checked > 1'000'000);
    CHECK(wrong == 0);
    CHECK(linear_to_srgb8(-0.0f) == 0);
    CHECK(linear_to_srgb8(-5) == 0);
    CHECK(linear_to_srgb8(7) == 255);
    CHECK(linear_to_srgb8(std::numeric_limits<float>::infinity()) == 255);
    CHECK(linear_to_srgb8(std::numeric_limits<float>::quiet_NaN()) == 0);
    // A whole image's codes (what a PNG is written from) are each value's, channel by channel.
    std::vector<Color> pixels;
    for (std::uint32_t bits = 0; bits <= one + 40000; bits += 4099)
        pixels.push_back(
            Color(std::bit_cast<float>(bits), -std::bit_cast<float>(bits), std::bit_cast<float>(one - bits / 2)));
    pixels.push_back(Color(std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(), 1));
    std::vector<std::uint8_t> codes(3 * pixels.size());
    linear_to_srgb8(pixels, codes.data());
    long differ = 0;
    for (std::size_t i = 0; i < pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) differ += codes[3 * i + std::size_t(c)] != linear_to_srgb8(pixels[i][c]);
    CHECK(differ == 0);
    CHECK(codes[codes.size() - 3] == 0);
    CHECK(codes[codes.size() - 2] == 255);
    CHECK(codes[codes.size() - 1] == 255);
}

TEST_CASE("PNG: written sRGB, read back to within one 8-bit step") {
    const fs::path dir = temp_dir();
    const Image img = gradient(33, 17);
    write_image(img, (dir / "g.png").string());
    const Image back = read_png((dir / "g.png").string());
    REQUIRE(back.width == 33);
    REQUIRE(back.height == 17);
    for (std::size_t i = 0; i < img.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            CHECK(std::abs(linear_to_srgb(back.pixels[i][c]) - linear_to_srgb(img.pixels[i][c])) <= 0.5f / 255 + 1e-6f);
    CHECK(back.at(0, 0).r == 0);  // row 0 stays the top row
    CHECK(back.at(0, 16).g == doctest::Approx(1));
    fs::remove_all(dir);
}

TEST_CASE("PFM: float data round-trips exactly, top row first in memory") {
    const fs::path dir = temp_dir();
    Image img = gradient(5, 4);
    img.at(2, 1) = Color(1e-9f, 123.5f, -2.0f);  // PFM keeps what PNG cannot
    write_image(img, (dir / "g.pfm").string());
    const Image back = read_pfm((dir / "g.pfm").string());
    CHECK(same_bits(img, back));
    fs::remove_all(dir);
}

TEST_CASE("image writers never leave a half file") {
    const fs::path dir = temp_dir();
    // A missing directory is created.
    write_image(gradient(4, 4), (dir / "a" / "b" / "c.png").string());
    CHECK(fs::exists(dir / "a" / "b" / "c.png"));
    // An unknown extension is refused before anything is written.
    CHECK_THROWS_WITH_AS(write_image(gradient(4, 4), (dir / "x.jpg").string()),
                         doctest::Contains("extension must be .png or .pfm"), std::runtime_error);
    // A target that cannot be created: an error, and no temporary left behind.
    const fs::path blocked = dir / "file";
    std::ofstream(blocked) << "not a directory";
    CHECK_THROWS_AS(write_image(gradient(4, 4), (blocked / "x.png").string()), std::runtime_error);
    int leftovers = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        leftovers += e.path().string().find(".tmp.") != std::string::npos;
    CHECK(leftovers == 0);
    fs::remove_all(dir);
}

TEST_CASE("bad image files give one clear error") {
    const fs::path dir = temp_dir();
    std::ofstream(dir / "junk.png") << "this is not a PNG";
    CHECK_THROWS_WITH_AS(read_png((dir / "junk.png").string()), doctest::Contains("cannot read image"),
                         std::runtime_error);
    CHECK_THROWS_AS(read_png((dir / "missing.png").string()), std::runtime_error);
    std::ofstream(dir / "short.pfm") << "PF\n4 4\n-1.0\nabc";
    CHECK_THROWS_WITH_AS(read_pfm((dir / "short.pfm").string()),
                         doctest::Contains("holds 3 bytes of pixels, not 192 for 4x4"), std::runtime_error);
    std::ofstream(dir / "huge.pfm") << "PF\n999999999 4\n-1.0\n";
    CHECK_THROWS_AS(read_pfm((dir / "huge.pfm").string()), std::runtime_error);
    fs::remove_all(dir);
}

TEST_CASE("Sampler: uniform in [0, 1), reproducible per (seed, pixel), distinct across pixels") {
    Sampler a(5, 17), b(5, 17), c(5, 18), d(6, 17);
    double sum = 0;
    bool differs_pixel = false, differs_seed = false;
    for (int i = 0; i < 10000; ++i) {
        const Real x = a.get1(Dimension::pixel);
        CHECK(x >= 0);
        CHECK(x < 1);
        CHECK(x == b.get1(Dimension::pixel));
        differs_pixel |= x != c.get1(Dimension::pixel);
        differs_seed |= x != d.get1(Dimension::pixel);
        sum += x;
    }
    CHECK(differs_pixel);
    CHECK(differs_seed);
    CHECK(sum / 10000 == doctest::Approx(0.5).epsilon(0.02));
}

TEST_CASE("Sampler: named dimensions are independent streams") {
    // Drawing any amount from one dimension never shifts what another one returns: a chapter
    // that takes more light samples keeps its lens and time samples.
    Sampler plain(3, 40), busy(3, 40);
    for (int i = 0; i < 37; ++i) (void)busy.get2(Dimension::light);
    for (int i = 0; i < 100; ++i) {
        CHECK(plain.get1(Dimension::lens) == busy.get1(Dimension::lens));
        CHECK(plain.get2(Dimension::time) == busy.get2(Dimension::time));
    }
    // And the dimensions differ from one another: no two share a sequence.
    Sampler s(3, 40);
    Real first[kDimensions];
    for (std::size_t d = 0; d < kDimensions; ++d) first[d] = s.get1(Dimension(d));
    for (std::size_t d = 0; d < kDimensions; ++d)
        for (std::size_t e = d + 1; e < kDimensions; ++e) CHECK(first[d] != first[e]);
    // Neighbouring pixels do not share a dimension's stream either (the stream number mixes
    // pixel and dimension: pixel p, dimension d+1 must not be pixel p+1, dimension d).
    Sampler p0(3, 0), p1(3, 1);
    const Real a = p0.get1(Dimension::lens), b = p1.get1(Dimension::pixel);
    CHECK(a != b);
}

TEST_CASE("render: bit-identical images for any thread count") {
    const Scene scene = jittered_scene();
    RenderOptions o;
    o.width = 67;  // not a multiple of the tile size
    o.height = 45;
    o.spp = 4;
    o.seed = 99;
    o.threads = 1;
    const RenderResult one = render(scene, o);
    o.threads = 2;
    const RenderResult two = render(scene, o);
    o.threads = 5;
    const RenderResult five = render(scene, o);
    CHECK(same_bits(one.image, two.image));
    CHECK(same_bits(one.image, five.image));
    CHECK(one.counters.of(RayKind::camera) == 67u * 45u * 4u);
    CHECK(one.counters.total() == one.counters.of(RayKind::camera));  // nothing but camera rays yet
    CHECK(five.counters.of(RayKind::camera) == one.counters.of(RayKind::camera));

    o.seed = 100;  // another seed moves the jittered samples
    CHECK_FALSE(same_bits(one.image, render(scene, o).image));
}

TEST_CASE("render: one sample per pixel is the pixel centre, whatever the seed") {
    const Scene scene = jittered_scene();
    RenderOptions o;
    o.width = 20;
    o.height = 10;
    o.seed = 1;
    const Image a = render(scene, o).image;
    o.seed = 2;
    CHECK(same_bits(a, render(scene, o).image));
}

TEST_CASE("render and pick reject bad requests") {
    const Scene scene = jittered_scene();
    RenderOptions o;
    o.width = 0;
    CHECK_THROWS_AS(render(scene, o), std::invalid_argument);
    o.width = 10;
    o.height = 10;
    CHECK_THROWS_WITH_AS(pick(scene, o, 10, 0), doctest::Contains("outside"), std::invalid_argument);
    Scene empty;
    CHECK_THROWS_AS(render(empty, o), std::invalid_argument);
}

TEST_CASE("pick: what the centre pixel sees") {
    const Scene scene = jittered_scene();
    RenderOptions o;
    o.width = 41;
    o.height = 41;
    const Pick p = pick(scene, o, 20, 20);
    CHECK(p.ray.origin == Vec3(0));
    REQUIRE(p.hit.has_value());
    CHECK(scene.surfaces.name(p.hit->surface) == "s");
    // The centre ray is the view direction (0, 0, -1); the sphere at (0.2, 0.1, -3) of radius
    // 1 meets it at z = -3 + sqrt(1 - 0.05).
    CHECK(p.hit->t == doctest::Approx(3 - std::sqrt(0.95)).epsilon(1e-6));
    const Pick corner = pick(scene, o, 0, 0);
    CHECK_FALSE(corner.hit.has_value());
    CHECK(corner.ray.direction.y > 0);  // row 0 is the top of the image
    CHECK(corner.ray.direction.x < 0);
}

TEST_CASE("round_to_float rounds values side by side (GCC 12.2 folds the plain conversion away)") {
    // A mesh's points rounded in one loop, x, y and z side by side: the pattern GCC's
    // vectoriser turns into a no-op when written Real(float(x)) (at -O2, this test's build).
    // The fast path's float blocks (book §10.5) rely on it.
    std::vector<Vec3> points{Vec3(0.1, 0.2, 0.3), Vec3(Real(1) / 3, 0.7, 0.9)};
    for (Vec3& p : points) p = Vec3(round_to_float(p.x), round_to_float(p.y), round_to_float(p.z));
    CHECK(points[0] == Vec3(0.1f, 0.2f, 0.3f));
    CHECK(points[1] == Vec3(1.0f / 3, 0.7f, 0.9f));
    CHECK(round_to_float(Real(0.5)) == Real(0.5));
}

TEST_CASE("float_below and float_above give the nearest float on each side, whatever the sign") {
    // The wide BVH's rays are made of these (core/wide_bvh.hpp): a float that is not below
    // the origin (or one more than a step away) loses boxes or costs visits.
    const auto check = [](Real x) {
        CAPTURE(x);
        const float lo = float_below(x), hi = float_above(x);
        CHECK(Real(lo) <= x);
        CHECK(Real(hi) >= x);
        // Nearest: the next float up from lo is above x (unless lo is x), and down from hi below.
        if (Real(lo) != x) CHECK(Real(std::nextafter(lo, std::numeric_limits<float>::infinity())) > x);
        if (Real(hi) != x) CHECK(Real(std::nextafter(hi, -std::numeric_limits<float>::infinity())) < x);
    };
    for (Real x : {Real(0), -Real(0), Real(1), Real(-1), Real(0.1), Real(-0.1), Real(1) / 3, -Real(1) / 3,
                   Real(std::numeric_limits<float>::max()), -Real(std::numeric_limits<float>::max()),
                   Real(std::numeric_limits<float>::denorm_min()), Real(1e-30), Real(-1e-30)})
        check(x);
    if constexpr (sizeof(Real) > sizeof(float)) {
        check(Real(1e-50));  // below float's smallest: rounds to +-0, and the wrong side steps to +-denorm_min
        check(Real(-1e-50));
        CHECK(float_below(Real(1e-50)) == 0.0f);
        CHECK(float_below(Real(-1e-50)) == -std::numeric_limits<float>::denorm_min());
        CHECK(float_above(Real(1e-50)) == std::numeric_limits<float>::denorm_min());
    }
    CHECK(float_below(kInfinity) == std::numeric_limits<float>::infinity());
    CHECK(float_below(-kInfinity) == -std::numeric_limits<float>::infinity());
    CHECK(std::signbit(float_below(Real(0))) == false);  // exact: kept as it is
    pcg32 rng(7);
    for (int i = 0; i < 10000; ++i) {
        const double u = std::ldexp(double(rng()) / 4294967296.0, int(rng(40)) - 20);
        check(Real(rng(2) ? u : -u));
    }
}

TEST_CASE("float_bounds rounds a point's three coordinates as float_below and float_above round each") {
    // The wide BVH's per-ray set-up does the three at once in vector lanes, with its own
    // step of the bits; it must agree with the scalar form bit for bit, signs of zero included.
    const auto same = [](float a, float b) {
        return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
    };
    const auto check = [&](const Vec3& p) {
        CAPTURE(p.x);
        CAPTURE(p.y);
        CAPTURE(p.z);
        float below[3], above[3];
        float_bounds(p, below, above);
        for (int a = 0; a < 3; ++a) {
            CHECK(same(below[a], float_below(p[a])));
            CHECK(same(above[a], float_above(p[a])));
        }
    };
    const Real edge[] = {Real(0),
                         -Real(0),
                         Real(1),
                         Real(-1),
                         Real(0.1),
                         Real(-0.1),
                         Real(1e-50),
                         Real(-1e-50),
                         Real(std::numeric_limits<float>::denorm_min()),
                         Real(std::numeric_limits<float>::max()),
                         -Real(std::numeric_limits<float>::max()),
                         kInfinity,
                         -kInfinity};
    for (Real x : edge)
        for (Real y : edge) check(Vec3(x, y, Real(1) / 3));
    pcg32 rng(11);
    for (int i = 0; i < 10000; ++i) {
        Vec3 p;
        for (int a = 0; a < 3; ++a) {
            const double u = std::ldexp(double(rng()) / 4294967296.0, int(rng(60)) - 30);
            p[a] = Real(rng(2) ? u : -u);
        }
        check(p);
    }
}

TEST_CASE("search arrays of 2 MiB or more start on a 2 MiB boundary, smaller ones on their type's") {
    // What lets the kernel back them with huge pages (core/search_memory.hpp).
    std::vector<TriangleBlock, SearchAllocator<TriangleBlock>> big(kHugePage / sizeof(TriangleBlock) + 1);
    CHECK(reinterpret_cast<std::uintptr_t>(big.data()) % kHugePage == 0);
    big[big.size() - 1].count = 3;  // the whole array is usable
    CHECK(big.back().count == 3);
    std::vector<TriangleBlock, SearchAllocator<TriangleBlock>> small(3);
    CHECK(reinterpret_cast<std::uintptr_t>(small.data()) % alignof(TriangleBlock) == 0);
    small.resize(kHugePage / sizeof(TriangleBlock) * 2);  // grows from ordinary memory to the big kind
    CHECK(reinterpret_cast<std::uintptr_t>(small.data()) % kHugePage == 0);
}

TEST_CASE("a wide node's child references keep a leaf's first item and count, and an inner child's number") {
    for (std::uint32_t first : {0u, 1u, 12345u, kMaxLeafFirst})
        for (std::uint32_t count : {1u, 4u, kMaxLeafCount}) {
            const std::uint32_t ref = leaf_ref(first, count);
            CHECK(is_leaf(ref));
            CHECK(leaf_first(ref) == first);
            CHECK(leaf_count(ref) == count);
        }
    for (std::uint32_t node : {0u, 1u, 99999u, kLeafRef - 1}) CHECK_FALSE(is_leaf(node));
}

TEST_CASE("a wide node lists its slots near to far along each octant's diagonal, empty slots last") {
    const Mesh mesh(terrain(Vec3(0), 10, 1.5, 40));  // 3,200 triangles: many nodes, some not full
    const auto& nodes = mesh.accel().wide.nodes;
    REQUIRE(nodes.size() > 10);
    int partly_empty = 0;
    for (const WideNode<kMeshBvhWidth>& node : nodes) {
        int used = 0;
        for (int c = 0; c < kMeshBvhWidth; ++c) used += node.lo[0][c] <= node.hi[0][c];
        partly_empty += used < kMeshBvhWidth;
        for (int octant = 0; octant < 8; ++octant) {
            unsigned seen = 0;
            double last = -std::numeric_limits<double>::infinity();
            for (int p = 0; p < kMeshBvhWidth; ++p) {
                const int slot = int(node.order[p] >> 3 * octant & 7);
                seen |= 1u << slot;
                const bool empty = !(node.lo[0][slot] <= node.hi[0][slot]);
                CHECK(empty == (p >= used));
                if (empty) continue;
                double key = 0;  // the box centre along the octant's diagonal
                for (int a = 0; a < 3; ++a)
                    key += (octant >> a & 1 ? -1.0 : 1.0) * (double(node.lo[a][slot]) + double(node.hi[a][slot]));
                CHECK(key >= last);
                last = key;
            }
            CHECK(seen == 0xffu);  // a permutation of the slots
        }
    }
    CHECK(partly_empty > 0);
}

}  // TEST_SUITE("common")

namespace names_test {
enum class Three : std::uint8_t { zero, one, two };
enum class Alone { only };
}  // namespace names_test

// The compile-time count is what makes names_of refuse a table of the wrong length: if a
// compiler spelled template arguments differently, it would count wrong, and this says so.
static_assert(rt::names_detail::enumerator_count<names_test::Three>() == 3);
static_assert(rt::names_detail::enumerator_count<names_test::Alone>() == 1);
static_assert(rt::names_detail::enumerator_count<rt::AccelKind>() == 8);

TEST_CASE("names: an enum's names both ways, and the list a message gives") {
    constexpr auto names = names_of<names_test::Three>({"zero", "one", "two"});
    CHECK(std::string(names[names_test::Three::two]) == "two");
    CHECK(names.find("one") == names_test::Three::one);
    CHECK_FALSE(names.find("One").has_value());
    CHECK_FALSE(names.find("").has_value());
    CHECK(names.list() == "zero, one or two");
    CHECK(names_of<names_test::Alone>({"only"}).list() == "only");
    CHECK(names.values()[2] == names_test::Three::two);
    // The library's tables, as the scene format and the command line spell them.
    CHECK(kAccelNames.list() == "none, bvh-sort, bvh-midpoint, bvh-sah, grid, bsp-midpoint, bsp or fast");
    CHECK(kShadingNames.find("cost") == Shading::cost);
    CHECK(std::string(kRayKindNames[RayKind::refraction]) == "refraction");
    CHECK(std::string(kDimensionNames[Dimension::other]) == "other");
}
