#include "app/headless_runner.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <glm/geometric.hpp>
#include <optional>

#include "app/state_dump.h"
#include "raster/png_writer.h"
#include "view/frame_renderer.h"
#include "sim/energy.h"
#include "sim/scene_loader.h"
#include "sim/simulation.h"

namespace weft {
namespace {

void print_error(const std::string& where, const std::string& what) {
    std::fprintf(stderr, "error: %s: %s\n", where.c_str(), what.c_str());
}

// Loads and checks the scene; prints the error and returns nothing when it is bad.
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
    const float ground_height = view::ground_height_below(simulation.cloth(), simulation.colliders());
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
        raster::Framebuffer framebuffer(command_line.screenshot_width, command_line.screenshot_height);
        view::ClothView cloth_view(simulation.cloth());
        view::render_frame(framebuffer, view::scene_camera(*scene), simulation.cloth(), cloth_view,
                           view::FrameOptions{}, ground_height, simulation.colliders());
        std::string error;
        if (!raster::write_png(framebuffer, *command_line.screenshot_path, &error)) {
            print_error(*command_line.screenshot_path, error);
            return exit_bad_input;
        }
    }
    return status;
}

int run_text_preview(const CommandLine& command_line, const char* default_scene_path) {
    const std::string path = command_line.scene_path.value_or(default_scene_path);
    std::optional<Scene> scene = load_checked_scene(path, command_line.overrides);
    if (!scene) return exit_bad_input;
    Simulation simulation(*scene);
    std::printf("weft: %s (%s), %d x %d particles, %zu springs, %s at dt = %g s\n",
                scene->name.c_str(), path.c_str(), scene->cloth.rows, scene->cloth.cols,
                simulation.cloth().spring_count(), integrator_name(simulation.integrator()),
                simulation.dt());
    std::printf("The window demo is not built yet; simulating 5 s headless.\n");
    std::printf("%8s %14s %14s %12s\n", "t (s)", "energy (J)", "kinetic (J)", "lowest y (m)");
    const auto steps_per_report = static_cast<std::uint64_t>(0.5 / simulation.dt() + 0.5);
    for (int report_index = 1; report_index <= 10; ++report_index) {
        for (std::uint64_t s = 0; s < std::max<std::uint64_t>(steps_per_report, 1); ++s) {
            StepReport report = simulation.step();
            if (report.diverged()) {
                print_divergence(simulation, *report.divergence);
                return exit_diverged;
            }
        }
        const Energy energy = measure_energy(simulation.cloth(), simulation.force_field());
        double lowest = simulation.cloth().positions[0].y;
        for (const Vec3& x : simulation.cloth().positions) lowest = std::min(lowest, x.y);
        std::printf("%8.3f %14.6g %14.6g %12.4f\n", simulation.time(), energy.total(),
                    energy.kinetic, lowest);
    }
    return exit_ok;
}

}  // namespace weft
