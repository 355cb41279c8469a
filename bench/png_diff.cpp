// SPDX-License-Identifier: MIT
// litkit_png_diff A.png B.png [--diff out.png]: how close two pictures are.
// Prints the fraction of pixels whose channels all differ by at most 2/255,
// the largest difference, and with --diff a picture of where they differ
// (white: more than 2/255 apart, grey: 1–2, black: equal).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "litkit/image.hpp"

int main(int argc, char** argv) {
    if (argc != 3 && !(argc == 5 && std::string(argv[3]) == "--diff")) {
        std::fprintf(stderr, "usage: %s A.png B.png [--diff out.png]\n", argv[0]);
        return 2;
    }
    try {
        const litkit::Image a = litkit::read_png(argv[1]);
        const litkit::Image b = litkit::read_png(argv[2]);
        if (a.width != b.width || a.height != b.height) {
            std::fprintf(stderr, "sizes differ: %dx%d and %dx%d\n", a.width, a.height, b.width,
                         b.height);
            return 1;
        }
        litkit::Image diff(a.width, a.height);
        std::size_t within = 0, equal = 0;
        int largest = 0;
        std::size_t worst = 0;
        double sum = 0.0;
        const std::size_t pixels = static_cast<std::size_t>(a.width) * a.height;
        for (std::size_t i = 0; i < pixels; ++i) {
            int d = 0;
            for (int c = 0; c < 3; ++c) {
                const int e = std::abs(int(a.rgb[i * 3 + c]) - int(b.rgb[i * 3 + c]));
                d = std::max(d, e);
                sum += e;
            }
            if (d > largest) largest = d, worst = i;
            within += d <= 2;
            equal += d == 0;
            const std::uint8_t v = d == 0 ? 0 : d <= 2 ? 96 : 255;
            diff.rgb[i * 3] = diff.rgb[i * 3 + 1] = diff.rgb[i * 3 + 2] = v;
        }
        std::printf(
            "pixels=%zu equal=%.5f within_2=%.5f over_2=%zu max_diff=%d at=(%zu,%zu) "
            "mean_abs_diff=%.4f\n",
            pixels, double(equal) / pixels, double(within) / pixels, pixels - within, largest,
            worst % a.width, worst / a.width, sum / (pixels * 3.0));
        if (argc == 5) litkit::write_png(diff, argv[4]);
        return 0;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "litkit_png_diff: %s\n", error.what());
        return 1;
    }
}
