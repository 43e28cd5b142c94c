#include "raster/png_writer.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

// Declarations only: Debian's libstb already contains the implementation (stbi_write_png_to_func
// among its exported symbols), so STB_IMAGE_WRITE_IMPLEMENTATION must not be defined here.
#include <stb/stb_image_write.h>

namespace weft::raster {
namespace {

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};

// stb hands the encoded bytes to a callback; writing them ourselves (rather than through
// stbi_write_png's own fopen) lets us report open, write and close errors separately.
struct Sink {
    std::FILE* file;
    bool failed = false;
};

void write_to_sink(void* context, void* data, int size) {
    auto* sink = static_cast<Sink*>(context);
    if (sink->failed || size <= 0) return;
    if (std::fwrite(data, 1, static_cast<std::size_t>(size), sink->file) !=
        static_cast<std::size_t>(size)) {
        sink->failed = true;
    }
}

bool fail(std::string* error, const std::string& path, const std::string& reason) {
    if (error != nullptr) *error = "cannot write PNG '" + path + "': " + reason;
    return false;
}

}  // namespace

bool write_png(const Framebuffer& framebuffer, const std::string& path, std::string* error) {
    if (path.empty()) return fail(error, path, "empty path");
    errno = 0;
    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "wb"));
    if (!file) return fail(error, path, errno != 0 ? std::strerror(errno) : "cannot open");

    Sink sink{file.get()};
    const int stride = framebuffer.width() * 4;
    const int encoded =
        stbi_write_png_to_func(write_to_sink, &sink, framebuffer.width(), framebuffer.height(), 4,
                               framebuffer.colours().data(), stride);
    if (encoded == 0) return fail(error, path, "PNG encoding failed");
    if (sink.failed) return fail(error, path, "write error");
    if (std::fclose(file.release()) != 0) {
        return fail(error, path, errno != 0 ? std::strerror(errno) : "close failed");
    }
    return true;
}

}  // namespace weft::raster
