// The acne table of book §6.4: for the stress scene of render/acne.hpp at 10^0 ... 10^5 units
// from the origin, how many lit pixels each offset method wrongly puts in their own shadow
// (acne), and how many it lights although another surface is in the way (leaks). The
// counts do not depend on the machine; run it in a float and a double build for both
// columns of the book's table:
//
//   build/release/bin/bench_acne            (Real=double)
//   build/float/bin/bench_acne              (Real=float)
//   bench_acne --images DIR                 also writes DIR/acne-REAL-METHOD.png at 10^5
#include "render/acne.hpp"
#include "io/image_file.hpp"
#include "render/render.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

using namespace rt;

int main(int argc, char** argv) {
    std::string images;
    if (argc == 3 && std::strcmp(argv[1], "--images") == 0) {
        images = argv[2];
    } else if (argc != 1) {
        std::fprintf(stderr, "usage: bench_acne [--images DIR]\n");
        return 2;
    }
    const Offset methods[] = {
        {OffsetMethod::normal, Real(1e-4)}, {OffsetMethod::course, Real(1e-4)}, {OffsetMethod::robust, Real(1e-4)}};
    const int width = 320, height = 240;
    std::printf("Real=%s, %dx%d pixels, epsilon = 1e-4 for the normal and course methods\n\n", real_name(), width,
                height);
    std::printf(
        "| distance | lit pixels | normal: acne | normal: leaks | course: acne | course: leaks | robust: acne "
        "| robust: leaks |\n|---|---|---|---|---|---|---|---|\n");
    for (int e = 0; e <= 5; ++e) {
        const Real scale = Real(std::pow(10.0, e));
        std::printf("| 10^%d |", e);
        bool first = true;
        for (const Offset& m : methods) {
            const AcneCount c = count_acne(acne_scene(scale, m), width, height);
            if (first) std::printf(" %llu |", static_cast<unsigned long long>(c.lit));
            first = false;
            std::printf(" %llu | %llu |", static_cast<unsigned long long>(c.acne),
                        static_cast<unsigned long long>(c.leaks));
        }
        std::printf("\n");
    }
    if (!images.empty()) {
        RenderOptions o;
        o.width = 400;
        o.height = 300;
        for (const Offset& m : methods) {
            const RenderResult r = render(acne_scene(Real(1e5), m), o);
            const std::string path = images + "/acne-" + real_name() + "-" + kOffsetMethodNames[m.method] + ".png";
            write_image(r.image, path);
            std::printf("wrote %s\n", path.c_str());
        }
    }
    return 0;
}
