// libFuzzer target: the image readers behind rtlab-diff (PNG through stb, PFM). Every input
// must give an image of the size it claims with finite pixels, or one line of error.
#include "fuzz_support.hpp"
#include "io/image_file.hpp"

#include <cmath>
#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const rt::Image image = rt::decode_image(rt::fuzz::text(data, size), "fuzz");
        rt::fuzz::check(image.pixels.size() == std::size_t(image.width) * std::size_t(image.height), "pixel count");
        for (const auto& p : image.pixels)
            rt::fuzz::check(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b), "a pixel is not finite");
    } catch (const std::runtime_error& e) {
        rt::fuzz::one_line(e.what());
    }
    return 0;
}
