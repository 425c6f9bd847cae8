// Book §14.2, course Figures 9.27-9.29: where a pixel's samples go under each pattern. The
// points are the renderer's own: camera_sample() for sample k of the pixel, from a Sampler
// set up as the render loop sets it (random, regular or jittered strata, one seed and pixel
// for all three panels), so each panel is what that pattern gives one pixel of a render.
#include "core/sampler.hpp"
#include "kinds.hpp"
#include "render/render.hpp"
#include "render/strata.hpp"

#include <string>

namespace figures {

Canvas pixel_samples(const rt::Fields& in) {
    const auto [count, side, seed, pixel] = pixel_samples_of(in, 1024);

    Canvas c;
    double left = 0;
    for (const rt::PixelPattern pattern :
         {rt::PixelPattern::random, rt::PixelPattern::regular, rt::PixelPattern::jittered}) {
        const rt::Strata strata = rt::strata_of(rt::Antialiasing{pattern, rt::PixelFilter::box});
        rt::Sampler sampler(seed, pixel);
        sampler.set_strata(count, side, strata);
        c.box({left, 0}, {left + 1, 1}, Ink::surface);
        if (strata != rt::Strata::none)
            for (int k = 1; k < side; ++k) {
                const double s = double(k) / side;
                c.line({left + s, 0}, {left + s, 1}, Ink::guide, Stroke::dashed);
                c.line({left, s}, {left + 1, s}, Ink::guide, Stroke::dashed);
            }
        for (int k = 0; k < count; ++k) {
            sampler.start_sample(k);
            const rt::Vec2 film = rt::camera_sample(0, 0, rt::PixelFilter::box, sampler).film;
            c.dot({left + double(film.x), double(film.y)}, Ink::camera);
        }
        c.label({left + 0.5, 0}, std::string(rt::kPatternNames[pattern]), Ink::axis, 0, -22, Anchor::middle);
        left += 1.3;
    }
    return c;
}

}  // namespace figures
