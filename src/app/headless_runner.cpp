#include "app/headless_runner.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <glm/geometric.hpp>
#include <optional>

#include "app/state_dump.h"
#include "raster/png_writer.h"
#include "sim/energy.h"
#include "sim/scene_loader.h"
#include "sim/simulation.h"
#include "view/frame_renderer.h"

namespace weft {
namespace {

void print_error(const std::string& where, const std::string& what) {
    std::fprintf(stderr, "error: %s: %s\n", where.c_str(), what.c_str());
}

}  // namespace

std::optional<Scene> load_checked_scene(const std::string& path,
                                        const std::vector<std::string>& overrides) {
    SceneLoadResult loaded = load_scene_file(path, overrides);
    for (const std::string& warning : loaded.warnings)
        std::fprintf(stderr, "warning: %s\n", warning.c_str());
    if (!loaded.ok()) {
        std::fprintf(stderr, "%s\n", loaded.error->message().c_str());
        return std::nullopt;
    }
    if (auto why = Simulation::unsupported_feature(*loaded.scene)) {
        print_error(path, *why);
        return std::nullopt;
    }
    return loaded.scene;
}

namespace {

void print_divergence(const Simulation& simulation, const std::string& why) {
    std::fprintf(stderr, "diverged at t=%.6f: %s\n", simulation.time(), why.c_str());
}

}  // namespace

int run_headless(const CommandLine& command_line) {
    std::optional<Scene> scene =
        load_checked_scene(*command_line.scene_path, command_line.overrides);
    if (!scene) return exit_bad_input;
    // Open the dump before running, so an unwritable path fails at once, not after the run.
    std::ofstream dump;
    if (command_line.dump_path) {
        dump.open(*command_line.dump_path, std::ios::binary | std::ios::trunc);
        if (!dump) {
            print_error(*command_line.dump_path,
                        std::string("cannot write: ") + std::strerror(errno));
            return exit_bad_input;
        }
    }

    Simulation simulation(*scene);
    const float ground_height =
        view::ground_height_below(simulation.cloth(), simulation.colliders());
    int status = exit_ok;
    for (std::uint64_t step = 0; step < *command_line.steps; ++step) {
        StepReport report = simulation.step();
        if (report.diverged()) {
            print_divergence(simulation, *report.divergence);
            status = exit_diverged;
            break;
        }
    }
    if (dump.is_open()) {
        // Also written on divergence: the state that was caught is what one wants to look at.
        write_state_csv(simulation.cloth(), dump);
        dump.flush();
        if (!dump) {
            print_error(*command_line.dump_path, "write failed");
            return exit_bad_input;
        }
    }
    if (command_line.screenshot_path) {
        raster::Framebuffer framebuffer(command_line.screenshot_width,
                                        command_line.screenshot_height);
        view::ClothView cloth_view(simulation.cloth());
        WorkerPool pool(default_thread_count());  // bands: the same image on any count
        view::render_frame(framebuffer, view::scene_camera(*scene), simulation.cloth(), cloth_view,
                           view::FrameOptions{}, ground_height, simulation.colliders(), &pool);
        std::string error;
        if (!raster::write_png(framebuffer, *command_line.screenshot_path, &error)) {
            print_error(*command_line.screenshot_path, error);
            return exit_bad_input;
        }
    }
    return status;
}

}  // namespace weft
