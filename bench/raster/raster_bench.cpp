// Frame times of the rasterizer on the scene it exists for: a 128×128-vertex sheet
// (32 258 triangles) waving gently, shaded with the checker pattern, with its wireframe
// (48 641 unique edges) drawn on top, at 640×480 and 1280×720. Three views: the sheet filling
// most of the screen; the camera 7 cm from the cloth; the camera inside a fold — the last two
// are where simple rasterizers slow down, because near triangles cover huge areas or reach
// behind the eye.
//
// Each frame moves the sheet (untimed), then times: clear, shaded mesh, wireframe. Reports
// the median and the mean over the frames, per phase and in total, in milliseconds; and,
// separately, the mesh drawn with a flat shader, to show what rasterization costs before
// shading.
//
// Usage: weft_raster_bench [frames] [--png DIRECTORY]
//   frames: timed frames per case (default 60), after 5 untimed warm-up frames
//   --png:  also write each case's last frame to DIRECTORY/raster_bench_<view>_<size>.png
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "raster/camera.h"
#include "raster/framebuffer.h"
#include "raster/line_renderer.h"
#include "raster/mesh.h"
#include "raster/mesh_renderer.h"
#include "raster/png_writer.h"
#include "raster/triangle_rasterizer.h"

namespace {

using namespace weft::raster;
using Clock = std::chrono::steady_clock;

constexpr int grid_side = 128;  // vertices per side

struct Sheet {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<TriangleIndices> triangles;
    std::vector<LineIndices> edges;

    Sheet() {
        const std::size_t count = static_cast<std::size_t>(grid_side) * grid_side;
        positions.resize(count);
        normals.resize(count);
        for (int r = 0; r < grid_side; ++r) {
            for (int c = 0; c < grid_side; ++c) {
                uvs.emplace_back(static_cast<float>(c) / (grid_side - 1),
                                 static_cast<float>(r) / (grid_side - 1));
            }
        }
        for (std::uint32_t r = 0; r + 1 < grid_side; ++r) {
            for (std::uint32_t c = 0; c + 1 < grid_side; ++c) {
                const std::uint32_t i = r * grid_side + c;
                triangles.push_back({i, i + grid_side, i + 1});
                triangles.push_back({i + 1, i + grid_side, i + grid_side + 1});
            }
        }
        edges = unique_edges(triangles);
    }

    // Height of the sheet (along z) above the point (x, y) of its rest plane at `time`.
    static float height_at(float x, float y, float time) {
        return 0.10f * std::sin(3.0f * x + 1.3f * time) * std::cos(2.0f * y + 0.7f * time) +
               0.05f * std::sin(5.0f * y - time);
    }

    // A 2 m × 2 m sheet in the x–y plane, waving along z.
    void wave(float time) {
        for (std::size_t i = 0; i < positions.size(); ++i) {
            const float x = 2.0f * uvs[i].x - 1.0f, y = 1.0f - 2.0f * uvs[i].y;
            positions[i] = {x, y, height_at(x, y, time)};
        }
        compute_vertex_normals(positions, triangles, normals);
    }
};

struct Phases {
    std::vector<double> clear, mesh, wireframe, total, raster_only;
};

// The same triangles through the same clip / setup / traversal / depth test, with a flat
// shader and no varyings: what the frame costs before any shading.
void draw_flat(Framebuffer& fb, const Camera& camera, const Sheet& sheet) {
    const glm::mat4 view_projection = view_projection_matrix(camera, fb);
    std::vector<ClipVertex> vertices(sheet.positions.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        vertices[i].position = view_projection * glm::vec4(sheet.positions[i], 1.0f);
    }
    const RasterState state;
    auto flat = [](const Fragment&) { return Rgba8{200, 120, 80, 255}; };
    for (const TriangleIndices& t : sheet.triangles) {
        draw_triangle(fb, state, vertices[t[0]], vertices[t[1]], vertices[t[2]], flat);
    }
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double mean(const std::vector<double>& values) {
    double sum = 0.0;
    for (double v : values) sum += v;
    return sum / static_cast<double>(values.size());
}

double milliseconds(Clock::duration d) {
    return std::chrono::duration<double, std::milli>(d).count();
}

std::string cpu_model() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) == 0) {
            const std::size_t colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(colon + 2);
        }
    }
    return "unknown";
}

using CameraAt = Camera (*)(float time);

void run_case(const char* view_name, CameraAt camera_at, int width, int height, int frames,
              Sheet& sheet, const std::string& png_directory) {
    Framebuffer fb(width, height);
    SurfaceStyle style;
    style.pattern = SurfacePattern::checker;
    const Lighting lighting;
    const Rgba8 background{28, 30, 36, 255}, wire{20, 20, 20, 255};
    Phases phases;
    std::size_t covered = 0;
    for (int frame = -5; frame < frames; ++frame) {
        const float time = 0.05f * static_cast<float>(frame + 5);
        sheet.wave(time);
        const Camera camera = camera_at(time);
        const auto t0 = Clock::now();
        fb.clear(background);
        const auto t1 = Clock::now();
        draw_mesh(fb, camera, MeshView{sheet.positions, sheet.normals, sheet.triangles, sheet.uvs},
                  style, lighting);
        const auto t2 = Clock::now();
        draw_indexed_lines(fb, camera, sheet.positions, sheet.edges, wire);
        const auto t3 = Clock::now();
        if (frame < 0) continue;
        if (!png_directory.empty() && frame == frames - 1) {
            const std::string path = png_directory + "/raster_bench_" + view_name + "_" +
                                     std::to_string(width) + "x" + std::to_string(height) + ".png";
            std::string error;
            if (!write_png(fb, path, &error)) std::fprintf(stderr, "%s\n", error.c_str());
        }
        fb.clear(background);
        const auto t4 = Clock::now();
        draw_flat(fb, camera, sheet);
        phases.raster_only.push_back(milliseconds(Clock::now() - t4));
        phases.clear.push_back(milliseconds(t1 - t0));
        phases.mesh.push_back(milliseconds(t2 - t1));
        phases.wireframe.push_back(milliseconds(t3 - t2));
        phases.total.push_back(milliseconds(t3 - t0));
        // Coverage: the pixels the sheet's triangles cover, averaged over the frames.
        covered += static_cast<std::size_t>(std::count_if(fb.depths().begin(), fb.depths().end(),
                                                          [](float d) { return d < 1.0f; }));
    }
    const double coverage =
        100.0 * static_cast<double>(covered) / (static_cast<double>(width) * height * frames);
    std::printf("| %-6s | %4dx%-4d | %5.1f %% | %6.2f | %6.2f | %6.2f | %6.2f | %6.2f | %6.2f |\n",
                view_name, width, height, coverage, median(phases.clear), median(phases.mesh),
                median(phases.wireframe), median(phases.total), mean(phases.total),
                median(phases.raster_only));
}

}  // namespace

int main(int argc, char** argv) {
    int frames = 60;
    std::string png_directory;
    const char* usage =
        "usage: weft_raster_bench [FRAMES] [--png DIR]\n"
        "       weft_raster_bench --help | --version\n"
        "\n"
        "Times the CPU rasterizer drawing a 128x128 cloth-like sheet at 640x480 and 1280x720,\n"
        "FRAMES frames per case (default 60), and prints a Markdown table of milliseconds per\n"
        "frame (bench/raster/RESULTS.md). --png DIR also writes each case's last frame.\n";
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--help" || argument == "-h") {
            std::printf("%s", usage);
            return 0;
        }
        if (argument == "--version") {
            std::printf("weft_raster_bench %s\n", WEFT_VERSION);
            return 0;
        }
    }
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--png" && i + 1 < argc) {
            png_directory = argv[++i];
        } else if (!argument.empty() &&
                   argument.find_first_not_of("0123456789") == std::string::npos) {
            frames = std::max(1, std::atoi(argument.c_str()));
        } else {
            std::fprintf(stderr, "error: %s: expects FRAMES (a whole number) or --png DIR\n%s",
                         argument.c_str(), usage);
            return 2;
        }
    }
    Sheet sheet;
    std::printf(
        "weft_raster_bench: %zu vertices, %zu triangles, %zu wireframe edges, %d frames per case\n",
        sheet.positions.size(), sheet.triangles.size(), sheet.edges.size(), frames);
    std::printf("CPU: %s, %u hardware threads (the rasterizer uses one)\n", cpu_model().c_str(),
                std::thread::hardware_concurrency());
#ifdef __VERSION__
    std::printf("Compiler: %s, build type: %s\n", __VERSION__, WEFT_BUILD_TYPE);
#endif
#if !defined(__OPTIMIZE__) || !defined(NDEBUG)
    std::printf("WARNING: not an optimised release build; numbers are not meaningful\n");
#endif
    std::printf(
        "\nmilliseconds per frame; phases are medians, total is median and mean;\n"
        "flat: the mesh's triangles with a flat shader (rasterization without shading)\n\n");
    std::printf(
        "| view   | size      | covered | clear  | mesh   | wire   | total  | mean   | flat   |\n");
    std::printf(
        "|--------|-----------|---------|--------|--------|--------|--------|--------|--------|\n");
    // The sheet filling most of the view.
    const CameraAt overview = [](float) {
        return make_camera({0.35f, 0.25f, 2.1f}, {0.0f, 0.0f, 0.0f}, 50.0f);
    };
    // About 7 cm in front of the cloth, looking down into it: huge triangles fill the screen.
    const CameraAt near = [](float) {
        return make_camera({0.1f, 0.2f, 0.14f}, {-0.3f, -0.1f, -0.3f}, 60.0f);
    };
    // Inside a fold: the eye rides 1 cm behind the cloth, looking along it, so triangles
    // cross the near plane (5 cm) and reach behind the camera; the near plane cuts a hole.
    const CameraAt inside = [](float time) {
        const float z = Sheet::height_at(0.1f, 0.2f, time) - 0.01f;
        Camera camera = make_camera({0.1f, 0.2f, z}, {-0.5f, -0.1f, z + 0.08f}, 60.0f);
        camera.up = {0.0f, 0.0f, 1.0f};  // the cloth is a ceiling receding from the eye
        return camera;
    };
    for (auto [width, height] : {std::pair{640, 480}, std::pair{1280, 720}}) {
        run_case("full", overview, width, height, frames, sheet, png_directory);
        run_case("near", near, width, height, frames, sheet, png_directory);
        run_case("inside", inside, width, height, frames, sheet, png_directory);
    }
    return 0;
}
