// Book §18.1-18.2: a moving sphere over one pixel's exposure. Its place at each sample's time
// is the library's Sphere::at, the times those the render loop gives one pixel's samples
// (sample_line in the time dimension, jittered and shuffled, turned into a time by exercise
// 18.1's shutter_time), and the dashed box is exercise 18.2's swept box, which every search
// structure is built from. Below, the motion's clock from 0 to 1: the shutter's strata, and
// each sample's time, filled where the camera ray (cast at that time) hits the sphere.
#include "core/sampler.hpp"
#include "geometry/shape.hpp"
#include "kinds.hpp"
#include "render/camera.hpp"
#include "render/strata.hpp"

#include <string>
#include <vector>

namespace figures {

Canvas motion_blur(const rt::Fields& in) {
    const rt::Vec3 from = in.vec3("center"), to = in.vec3("moves_to");
    const rt::Sphere ball(from, in.length("radius"), to - from);
    const std::vector<rt::Real> shutter = in.numbers("shutter", 2, rt::limits::shutter);
    if (!(shutter[0] < shutter[1])) in.fail("shutter", "must open before it closes");
    const auto [count, side, seed, pixel] = pixel_samples_of(in);
    auto [ray, t_end] = ray_of(in);

    Canvas c;
    const rt::Box swept = rt::bounding_box(ball);
    c.polygon({flat(swept.min),
               {double(swept.max.x), double(swept.min.y)},
               flat(swept.max),
               {double(swept.min.x), double(swept.max.y)}},
              Ink::axis, false, Stroke::dashed);
    c.circle(flat(ball.at(0).center), double(ball.radius), Ink::guide, false, Stroke::dashed);
    c.label(flat(ball.at(0).center), "time 0", Ink::axis, 0, -6, Anchor::middle, true);
    c.circle(flat(ball.at(1).center), double(ball.radius), Ink::guide, false, Stroke::dashed);
    c.label(flat(ball.at(1).center), "time 1", Ink::axis, 0, -6, Anchor::middle, true);

    // The clock under the picture: time 0 under the swept box's left side, 1 under its right.
    const double x0 = double(swept.min.x), x1 = double(swept.max.x), size = double(ball.radius);
    const double y = double(swept.min.y) - 0.8 * size;
    auto clock = [&](rt::Real time) { return P2{x0 + (x1 - x0) * double(time), y}; };
    c.line(clock(0), clock(1), Ink::axis, Stroke::thin);
    c.box(clock(shutter[0]) - P2{0, 0.12 * size}, clock(shutter[1]) + P2{0, 0.12 * size}, Ink::surface);
    for (int k = 0; k <= count; ++k) {
        const P2 tick = clock(shutter[0] + (shutter[1] - shutter[0]) * rt::Real(k) / rt::Real(count));
        c.line(tick - P2{0, 0.12 * size}, tick + P2{0, 0.12 * size}, Ink::guide, Stroke::thin);
    }
    c.label(clock(0), "0", Ink::axis, 0, -28, Anchor::middle, true);
    c.label(clock(1), "1", Ink::axis, 0, -28, Anchor::middle, true);
    c.label(clock((shutter[0] + shutter[1]) / 2), "shutter open", Ink::axis, 0, -28, Anchor::middle, true);

    rt::Sampler sampler(seed, pixel);
    sampler.set_strata(count, side, rt::Strata::jittered);
    int hits = 0;
    for (int k = 0; k < count; ++k) {
        sampler.start_sample(k);
        const rt::LineSample s = rt::sample_line(sampler, rt::Dimension::time);
        ray.time = rt::shutter_time(s.stratum, s.count, s.u, shutter[0], shutter[1]);
        rt::HitRecord rec;
        const bool hit = rt::hit_record(ball, ray, rt::Interval{0, t_end}, rt::SurfaceRef{}, rec);
        hits += hit;
        c.circle(flat(ball.at(ray.time).center), double(ball.radius), hit ? Ink::camera : Ink::surface, false,
                 Stroke::thin);
        c.dot(clock(ray.time), Ink::camera, !hit);
    }
    c.arrow(flat(ray.origin), flat(ray.at(t_end)), Ink::camera);
    c.dot(flat(ray.origin), Ink::camera);
    c.label(flat(ray.origin), "the pixel's ray: hits in " + std::to_string(hits) + " of " + std::to_string(count),
            Ink::camera, 8, 0);
    return c;
}

}  // namespace figures
