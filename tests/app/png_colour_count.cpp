// weft_png_colour_count [--lines] IMAGE R G B [X0 X1 [Y0 Y1]]: prints how many pixels are
// within 6 levels of (R, G, B) in every channel, over the whole image or only the columns
// X0 <= x < X1 (and rows Y0 <= y < Y1). With --lines it prints instead how many separate
// bands of rows hold such a pixel: the lines of a message in that colour. For the
// end-to-end test: is a message drawn in its colour, where, and how many of its lines show?
// (Dear ImGui's text is drawn unblended from its pixel font, so a glyph's pixels carry the
// text colour exactly.)
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <stb/stb_image.h>

int main(int argc, char** argv) {
    const bool lines = argc > 1 && std::strcmp(argv[1], "--lines") == 0;
    if (lines) {
        --argc;
        ++argv;
    }
    if (argc != 5 && argc != 7 && argc != 9) {
        std::fprintf(stderr,
                     "usage: weft_png_colour_count [--lines] IMAGE R G B [X0 X1 [Y0 Y1]]\n");
        return 2;
    }
    int width = 0, height = 0, channels = 0;
    unsigned char* image = stbi_load(argv[1], &width, &height, &channels, 4);
    if (!image) {
        std::fprintf(stderr, "error: cannot read %s\n", argv[1]);
        return 2;
    }
    const int want[3] = {std::atoi(argv[2]), std::atoi(argv[3]), std::atoi(argv[4])};
    const int x0 = argc >= 7 ? std::atoi(argv[5]) : 0;
    const int x1 = argc >= 7 ? std::atoi(argv[6]) : width;
    const int y0 = argc == 9 ? std::atoi(argv[7]) : 0;
    const int y1 = argc == 9 ? std::atoi(argv[8]) : height;
    long long count = 0, bands = 0;
    bool last_row_held = false;
    for (long long y = y0 < 0 ? 0 : y0; y < y1 && y < height; ++y) {
        long long in_row = 0;
        for (long long x = x0 < 0 ? 0 : x0; x < x1 && x < width; ++x) {
            const unsigned char* pixel = image + 4 * (y * width + x);
            bool near = true;
            for (int c = 0; c < 3; ++c) near = near && std::abs(pixel[c] - want[c]) <= 6;
            in_row += near;
        }
        count += in_row;
        bands += in_row > 0 && !last_row_held;
        last_row_held = in_row > 0;
    }
    std::printf("%lld\n", lines ? bands : count);
    stbi_image_free(image);
    return 0;
}
