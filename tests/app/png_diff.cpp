// weft_png_diff A.png B.png: prints the fraction of pixels that differ by more than 8 levels
// in any channel (1 if the sizes differ). For the end-to-end test: did the view change?
#include <cstdio>
#include <cstdlib>

#include <stb/stb_image.h>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: weft_png_diff A.png B.png\n");
        return 2;
    }
    int wa = 0, ha = 0, wb = 0, hb = 0, channels = 0;
    unsigned char* a = stbi_load(argv[1], &wa, &ha, &channels, 4);
    unsigned char* b = stbi_load(argv[2], &wb, &hb, &channels, 4);
    if (!a || !b) {
        std::fprintf(stderr, "error: cannot read %s\n", !a ? argv[1] : argv[2]);
        return 2;
    }
    double fraction = 1.0;
    if (wa == wb && ha == hb) {
        long long differing = 0;
        for (long long p = 0; p < static_cast<long long>(wa) * ha; ++p)
            for (int c = 0; c < 3; ++c)
                if (std::abs(a[4 * p + c] - b[4 * p + c]) > 8) {
                    ++differing;
                    break;
                }
        fraction = static_cast<double>(differing) / (static_cast<double>(wa) * ha);
    }
    std::printf("%.6f\n", fraction);
    stbi_image_free(a);
    stbi_image_free(b);
    return 0;
}
