// weft_png_diff A.png B.png [X0 X1 [BX0 [Y0 Y1]]]: prints the fraction of pixels that differ
// by more than 8 levels in any channel, over the whole image or only the columns
// X0 <= x < X1 of A, compared with the same columns of B or, given BX0, with B's columns
// from BX0 on (1 if the heights differ, or the columns are not in both images); given Y0 and
// Y1, only in the rows Y0 <= y < Y1. For the end-to-end test: did the view (or one run's
// column of it, or the panel's plots) change? Is the view shown whole beside the panel?
#include <cstdio>
#include <cstdlib>

#include <stb/stb_image.h>

int main(int argc, char** argv) {
    if (argc != 3 && argc != 5 && argc != 6 && argc != 8) {
        std::fprintf(stderr, "usage: weft_png_diff A.png B.png [X0 X1 [BX0 [Y0 Y1]]]\n");
        return 2;
    }
    int wa = 0, ha = 0, wb = 0, hb = 0, channels = 0;
    unsigned char* a = stbi_load(argv[1], &wa, &ha, &channels, 4);
    unsigned char* b = stbi_load(argv[2], &wb, &hb, &channels, 4);
    if (!a || !b) {
        std::fprintf(stderr, "error: cannot read %s\n", !a ? argv[1] : argv[2]);
        return 2;
    }
    const int x0 = argc >= 5 ? std::atoi(argv[3]) : 0;
    const int x1 = argc >= 5 ? std::atoi(argv[4]) : wa;
    const int bx0 = argc >= 6 ? std::atoi(argv[5]) : x0;
    const int y0 = argc == 8 ? std::atoi(argv[6]) : 0;
    const int y1 = argc == 8 ? std::atoi(argv[7]) : ha;
    // Without an offset the images must be the same size: a view that changed size changed.
    const bool comparable = argc >= 6 ? ha == hb : wa == wb && ha == hb;
    double fraction = 1.0;
    if (comparable && 0 <= x0 && x0 < x1 && x1 <= wa && 0 <= bx0 && bx0 + (x1 - x0) <= wb &&
        0 <= y0 && y0 < y1 && y1 <= ha) {
        long long differing = 0;
        for (long long y = y0; y < y1; ++y)
            for (long long x = x0; x < x1; ++x) {
                const long long p = y * wa + x, q = y * wb + (x - x0 + bx0);
                for (int c = 0; c < 3; ++c)
                    if (std::abs(a[4 * p + c] - b[4 * q + c]) > 8) {
                        ++differing;
                        break;
                    }
            }
        fraction = static_cast<double>(differing) / (static_cast<double>(x1 - x0) * (y1 - y0));
    }
    std::printf("%.6f\n", fraction);
    stbi_image_free(a);
    stbi_image_free(b);
    return 0;
}
