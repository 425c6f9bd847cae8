// Book §15.2: how a pixel's samples are paired with points of an area light. Left, the
// pixel's jittered samples, numbered k; right, the parallelogram light (corner c, edges a and
// b, course Figure 9.32) with the point each sample k lights from. Both come from one Sampler
// set up as the render loop sets it: camera_sample() for the film, and for the light
// sample_square(Dimension::light), whose strata Sampler::stratum shuffles against the
// pixel's (exercise 15.1), placed by exercise 15.2's light_point. The pixel's bottom row is
// filled on both sides: in step it would light from the light's bottom row; shuffled, it
// lights from all over the light.
#include "core/sampler.hpp"
#include "kinds.hpp"
#include "render/strata.hpp"
#include "shading/light.hpp"

#include <algorithm>
#include <string>

namespace figures {

Canvas stratum_pairing(const rt::Fields& in) {
    const auto [count, side, seed, pixel] = pixel_samples_of(in);
    const rt::Fields lf = in.object("light");
    rt::Light light;
    light.type = rt::Light::Type::parallelogram;
    light.position = lf.vec3("corner");
    light.edge_a = lf.vec3("edge_a");
    light.edge_b = lf.vec3("edge_b");
    lf.done();
    const rt::Real la = glm::length(light.edge_a);
    const rt::Vec3 ea = light.edge_a / la;
    const rt::Vec3 across = light.edge_b - glm::dot(light.edge_b, ea) * ea;
    if (!(glm::length(across) > 1e-6 * la)) in.fail("light", "its edges must not be parallel");
    const rt::Vec3 eb = across / glm::length(across);

    // The light drawn in its own plane, to the right of the unit pixel, scaled to its height.
    const double scale = 1.0 / std::max(double(la), double(glm::length(light.edge_b))), right = 1.5;
    auto on_light = [&](const rt::Vec3& q) {
        const rt::Vec3 v = q - light.position;
        return P2{right + scale * double(glm::dot(v, ea)), scale * double(glm::dot(v, eb))};
    };

    Canvas c;
    c.box({0, 0}, {1, 1}, Ink::surface);
    const P2 c0 = on_light(light.position), ca = on_light(light.position + light.edge_a),
             cb = on_light(light.position + light.edge_b), cab = on_light(light.position + light.edge_a + light.edge_b);
    c.polygon({c0, ca, cab, cb}, Ink::light);
    for (int k = 1; k < side; ++k) {
        const double s = double(k) / side;
        c.line({s, 0}, {s, 1}, Ink::guide, Stroke::dashed);
        c.line({0, s}, {1, s}, Ink::guide, Stroke::dashed);
        c.line(c0 + s * (ca - c0), cb + s * (ca - c0), Ink::guide, Stroke::dashed);
        c.line(c0 + s * (cb - c0), ca + s * (cb - c0), Ink::guide, Stroke::dashed);
    }
    c.label(c0, "c", Ink::light, -6, -16, Anchor::end);
    c.arrow(c0, ca, Ink::light);
    c.label(ca, "a", Ink::light, 6, -16);
    c.arrow(c0, cb, Ink::light);
    c.label(cb, "b", Ink::light, -6, 0, Anchor::end);

    rt::Sampler sampler(seed, pixel);
    sampler.set_strata(count, side, rt::Strata::jittered);
    for (int k = 0; k < count; ++k) {
        sampler.start_sample(k);
        const rt::Vec2 film = rt::camera_sample(0, 0, rt::PixelFilter::box, sampler).film;
        const P2 on_pixel{double(film.x), double(film.y)};
        const P2 lit = on_light(rt::light_point(light, rt::sample_square(sampler, rt::Dimension::light)));
        const bool bottom = k < side;  // the pixel's strata are taken row by row from the bottom
        c.dot(on_pixel, Ink::camera, !bottom);
        c.dot(lit, Ink::camera, !bottom);
        c.label(on_pixel, std::to_string(k), Ink::axis, 5, 3, Anchor::start, true);
        c.label(lit, std::to_string(k), Ink::axis, 5, 3, Anchor::start, true);
    }
    c.label({0.5, 0}, "pixel", Ink::axis, 0, -22, Anchor::middle);
    c.label(0.5 * (c0 + ca), "light", Ink::axis, 0, -22, Anchor::middle);
    return c;
}

}  // namespace figures
