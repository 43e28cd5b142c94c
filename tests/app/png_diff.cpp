// weft_png_diff A.png B.png [X0 X1]: prints the fraction of pixels that differ by more than 8
// levels in any channel (1 if the sizes differ), over the whole image or only the columns
// X0 <= x < X1. For the end-to-end test: did the view (or one run's column of it) change?
#include <cstdio>
#include <cstdlib>

#include <stb/stb_image.h>

int main(int argc, char** argv) {
    if (argc != 3 && argc != 5) {
        std::fprintf(stderr, "usage: weft_png_diff A.png B.png [X0 X1]\n");
        return 2;
    }
    int wa = 0, ha = 0, wb = 0, hb = 0, channels = 0;
    unsigned char* a = stbi_load(argv[1], &wa, &ha, &channels, 4);
    unsigned char* b = stbi_load(argv[2], &wb, &hb, &channels, 4);
    if (!a || !b) {
        std::fprintf(stderr, "error: cannot read %s\n", !a ? argv[1] : argv[2]);
        return 2;
    }
    const int x0 = argc == 5 ? std::atoi(argv[3]) : 0;
    const int x1 = argc == 5 ? std::atoi(argv[4]) : wa;
    double fraction = 1.0;
    if (wa == wb && ha == hb && 0 <= x0 && x0 < x1 && x1 <= wa) {
        long long differing = 0;
        for (long long y = 0; y < ha; ++y)
            for (long long x = x0; x < x1; ++x) {
                const long long p = y * wa + x;
                for (int c = 0; c < 3; ++c)
                    if (std::abs(a[4 * p + c] - b[4 * p + c]) > 8) {
                        ++differing;
                        break;
                    }
            }
        fraction = static_cast<double>(differing) / (static_cast<double>(x1 - x0) * ha);
    }
    std::printf("%.6f\n", fraction);
    stbi_image_free(a);
    stbi_image_free(b);
    return 0;
}
