// The core layer's parts no exercise implements: the limits table and its messages, text
// made safe for one line and for XML, unit vectors at the ends of the range, the Sampler's
// streams, and the flat BVH's parallel build.
#include "core/flat_bvh.hpp"
#include "core/limits.hpp"
#include "core/sampler.hpp"
#include "core/text.hpp"
#include "core/xml.hpp"
#include "geometry/limits.hpp"
#include "render/strata.hpp"
#include "support.hpp"
#include "support/box_searches.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <tbb/task_arena.h>
#include <pcg_random.hpp>

using namespace rt;

TEST_SUITE("common") {
TEST_CASE("Sampler: only a sample's first point in a dimension takes its stratum") {
    // A second glossy bounce or a second area light in the same sample gets an independent
    // point: one tied to the first stratum would bias a path that depends on both.
    Sampler s(4, 2);
    s.set_strata(16, 4, Strata::jittered);
    s.start_sample(3);
    CHECK(s.take_stratum(Dimension::glossy));
    CHECK_FALSE(s.take_stratum(Dimension::glossy));
    CHECK_FALSE(s.take_stratum(Dimension::glossy));
    CHECK(s.take_stratum(Dimension::light));  // each dimension its own
    s.start_sample(4);
    CHECK(s.take_stratum(Dimension::glossy));  // and each sample
    Sampler plain(4, 2);
    plain.set_strata(10, 0, Strata::jittered);  // 10 is not a square: no strata at all
    CHECK(plain.strata() == Strata::none);
    plain.start_sample(0);
    CHECK_FALSE(plain.take_stratum(Dimension::lens));
}

TEST_CASE("Sampler: one moved from pixel to pixel draws what a new one for each pixel draws") {
    // The render loop keeps one sampler per tile (render/render.cpp): its streams are seeded
    // at their first draw and its strata orders shuffled again for each pixel, so every image
    // is what a sampler per pixel made. Pixels that draw nothing in a dimension are between
    // ones that do, and the reused sampler is moved on from a pixel mid-sample.
    const auto draws = [](Sampler& s, std::uint64_t pixel) {
        std::vector<double> out;
        s.set_strata(9, 3, Strata::jittered);
        for (int k = 0; k < 9; ++k) {
            s.start_sample(k);
            const Vec2 film = sample_square(s, Dimension::pixel);
            out.insert(out.end(), {double(film.x), double(film.y)});
            if (pixel % 3 != 1) {  // every third pixel leaves the lens and light dimensions alone
                const Vec2 lens = sample_square(s, Dimension::lens);
                out.insert(out.end(), {double(lens.x), double(lens.y), double(s.get1(Dimension::light))});
            }
        }
        return out;
    };
    Sampler reused(11, 0);
    for (std::uint64_t pixel = 40; pixel < 52; ++pixel) {
        reused.start_pixel(pixel);
        Sampler fresh(11, pixel);
        CHECK(draws(reused, pixel) == draws(fresh, pixel));
    }
}

TEST_CASE("Sampler: a second point in a dimension is independent of the first") {
    // Two glossy points per sample, 16 jittered samples per pixel, over 2,000 pixels: if the
    // second took the first's stratum, x1 and x2 would share a quarter of [0, 1), and E[x1 x2]
    // would be about the mean square of the four stratum centres, 0.328; independent, 0.25.
    double sum = 0;
    int n = 0;
    for (std::uint64_t pixel = 0; pixel < 2000; ++pixel) {
        Sampler s(9, pixel);
        s.set_strata(16, 4, Strata::jittered);
        for (int k = 0; k < 16; ++k) {
            s.start_sample(k);
            const Vec2 a = sample_square(s, Dimension::glossy), b = sample_square(s, Dimension::glossy);
            sum += double(a.x) * double(b.x);
            ++n;
        }
    }
    // 32,000 products of spread about 0.2: the mean is 0.25 to within 0.004 (3.5 sigma).
    CHECK(std::abs(sum / n - 0.25) < 0.004);
}

TEST_CASE("limits: one table, messages that name the limit, numbers written as people write them") {
    CHECK(limits::refuse(limits::icosphere_subdivisions, 9) == "icosphere subdivisions must be in 0..7, not 9");
    CHECK(limits::refuse(limits::length, -1) == "length must be in 1e-6..1e8, not -1");
    CHECK(limits::refuse(limits::radiance, 1e39) == "radiance must be in 0..1000000, not 1e39");
    CHECK(limits::refuse(limits::field_of_view, 180) == "field of view must be in 0.001..179.9 degrees, not 180");
    CHECK(limits::describe(limits::triangle_vertices) == "must be 3");
    CHECK_FALSE(limits::contains(limits::coordinate, std::nan("")));
    for (const auto& r : limits::all) {
        CAPTURE(r.name);
        CHECK(r.min <= r.max);
        // Every value a scene may hold stays finite and, where it must be positive, non-zero
        // as a float: colours are float whatever Real is.
        if (*r.schema) {
            CHECK(std::isfinite(float(r.max)));
            CHECK(std::isfinite(float(r.min)));
            if (r.min > 0) CHECK(float(r.min) > 0);
        }
    }
    // The products the ray tests form stay far from float's range: (2 * max)^3.
    CHECK(std::pow(2 * limits::coordinate.max, 3) < 1e-10 * std::numeric_limits<float>::max());
}

TEST_CASE("one_line: control characters become escapes, UTF-8 stays") {
    CHECK(one_line("a\nb\tc\x1b[31m") == "a\\nb\\tc\\x1b[31m");
    CHECK(one_line("caf\xc3\xa9") == "caf\xc3\xa9");
    CHECK(one_line(std::string("\0x", 2)) == "\\x00x");
}

TEST_CASE("xml_escape: the four specials become entities, control characters go, UTF-8 stays") {
    CHECK(xml_escape("a<b & \"c\">") == "a&lt;b &amp; &quot;c&quot;&gt;");
    CHECK(xml_escape("line\none\t\x1b") == "lineone");
    CHECK(xml_escape("\xce\xb8 \xe2\x82\x81") == "\xce\xb8 \xe2\x82\x81");  // θ ₁: a label's Greek and subscripts
    CHECK(xml_escape("it's") == "it's");
}

TEST_CASE("unit_vector: any finite non-zero vector, huge or tiny, in float as in double") {
    const Real big = std::numeric_limits<Real>::max() / 4, tiny = std::numeric_limits<Real>::denorm_min() * 8;
    for (const Vec3& v :
         {Vec3(0, -big, 0), Vec3(big, big, big), Vec3(0, tiny, 0), Vec3(tiny, -tiny, 0), Vec3(3, 4, 0)}) {
        CAPTURE(v);
        const Vec3 u = unit_vector(v);
        CHECK(std::abs(glm::length(u) - 1) < 4 * std::numeric_limits<Real>::epsilon());
        CHECK(glm::dot(u, v) > 0);
    }
    CHECK(unit_vector(Vec3(3, 4, 0)) == Vec3(Real(0.6), Real(0.8), 0));
    CHECK(unit_vector(Vec3(0)) == Vec3(0));
}

TEST_CASE("flat BVH: the parallel build lays out the same tree on 1 thread as on 2, and it is whole") {
    // 30,000 boxes of mixed sizes, clustered and spread, so the top levels split in parallel.
    pcg32 rng(7);
    const auto u = [&] { return Real(rng()) / Real(4294967296.0); };
    std::vector<Box> boxes;
    for (int k = 0; k < 30000; ++k) {
        const Vec3 c = k % 3 ? Vec3(u(), u(), u()) * Real(100) : Vec3(u(), u(), u()) + Vec3(50);
        const Vec3 h = Vec3(u(), u(), u()) * Real(k % 7 ? 0.1 : 3);
        boxes.push_back(Box{c - h, c + h});
    }
    FlatBvh one, four;
    tbb::task_arena(1).execute([&] { one = build_bvh(boxes, 4); });
    tbb::task_arena(2).execute([&] { four = build_bvh(boxes, 4); });
    REQUIRE(one.nodes.size() == four.nodes.size());
    CHECK(std::memcmp(one.nodes.data(), four.nodes.data(), one.nodes.size() * sizeof(BvhNode)) == 0);
    CHECK(one.items == four.items);
    CHECK(one.depth == four.depth);
    // Whole: every item in exactly one leaf, inside that leaf's box and every ancestor's; each
    // inner node's children after it (the layout the serial build makes).
    std::vector<int> seen(boxes.size(), 0);
    long bad = 0;
    std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>> stack{{0u, {}}};
    while (!stack.empty()) {
        auto [at, path] = stack.back();
        stack.pop_back();
        const BvhNode& node = one.nodes[at];
        path.push_back(at);
        if (!node.leaf()) {
            bad += node.first <= at;
            stack.push_back({node.first, path});
            stack.push_back({node.first + 1, path});
            continue;
        }
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
            const Box& b = boxes[one.items[k]];
            ++seen[one.items[k]];
            for (const std::uint32_t p : path)
                for (int a = 0; a < 3; ++a) bad += !(one.nodes[p].lo[a] <= b.min[a] && b.max[a] <= one.nodes[p].hi[a]);
        }
    }
    CHECK(bad == 0);
    CHECK(std::count(seen.begin(), seen.end(), 1) == long(boxes.size()));
}
TEST_CASE("the wide BVH's searches, one ray and a packet at a time, find the nearest box (this build's lanes)") {
    rt::test::check_searches<4>();
    rt::test::check_searches<8>();
    rt::test::check_packet_searches();
}

}  // TEST_SUITE("common")
