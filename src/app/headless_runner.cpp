#include "app/headless_runner.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <glm/geometric.hpp>
#include <optional>

#include "app/demo_state.h"
#include "app/session_record.h"
#include "app/state_dump.h"
#include "app/status_text.h"
#include "raster/png_writer.h"
#include "sim/energy.h"
#include "sim/scene_loader.h"
#include "sim/simulation.h"
#include "sim/state_hash.h"
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

// The documented line, `diverged at t=SECONDS: WHY`, which scripts match and so stays as it
// is; then the same moment with its unit and its place in the run, for the reader a bare
// "t=0.012000" left guessing.
void print_divergence(const Simulation& simulation, const std::string& why, std::uint64_t step,
                      std::uint64_t steps) {
    std::fprintf(stderr, "diverged at t=%.6f: %s\n", simulation.time(), why.c_str());
    std::fprintf(stderr, "  that is %.6g s of simulated time, in step %llu of %llu (dt %g s)\n",
                 simulation.time(), static_cast<unsigned long long>(step),
                 static_cast<unsigned long long>(steps), simulation.dt());
}

}  // namespace

namespace {

// Opens the dump before running, so an unwritable path fails at once, not after the run.
bool open_dump(const CommandLine& command_line, std::ofstream& dump) {
    if (!command_line.dump_path) return true;
    dump.open(*command_line.dump_path, std::ios::binary | std::ios::trunc);
    if (dump) return true;
    print_error(*command_line.dump_path, std::string("cannot write: ") + std::strerror(errno));
    return false;
}

// Writes the dump and the screenshot asked for; false (after saying why) if one fails.
bool write_outputs(const CommandLine& command_line, std::ofstream& dump,
                   const Simulation& simulation) {
    if (dump.is_open()) {
        write_state_csv(simulation.cloth(), dump);
        dump.flush();
        if (!dump) {
            print_error(*command_line.dump_path, "write failed");
            return false;
        }
    }
    if (command_line.screenshot_path) {
        raster::Framebuffer framebuffer(command_line.screenshot_width,
                                        command_line.screenshot_height);
        view::ClothView cloth_view(simulation.cloth());
        WorkerPool pool(default_thread_count());  // bands: the same image on any count
        view::render_frame(framebuffer, view::scene_camera(simulation.scene()), simulation.cloth(),
                           cloth_view, view::FrameOptions{},
                           view::ground_height_below(simulation.cloth(), simulation.colliders()),
                           simulation.colliders(), &pool);
        std::string error;
        if (!raster::write_png(framebuffer, *command_line.screenshot_path, &error)) {
            print_error(*command_line.screenshot_path, error);
            return false;
        }
    }
    return true;
}

}  // namespace

int run_headless(const CommandLine& command_line) {
    std::optional<Scene> scene =
        load_checked_scene(*command_line.scene_path, command_line.overrides);
    if (!scene) return exit_bad_input;
    std::ofstream dump;
    if (!open_dump(command_line, dump)) return exit_bad_input;

    Simulation simulation(*scene);
    int status = exit_ok;
    for (std::uint64_t step = 0; step < *command_line.steps; ++step) {
        StepReport report = simulation.step();
        if (report.diverged()) {
            print_divergence(simulation, *report.divergence, step + 1, *command_line.steps);
            status = exit_diverged;
            break;
        }
    }
    // Also written on divergence: the state that was caught is what one wants to look at.
    if (!write_outputs(command_line, dump, simulation)) return exit_bad_input;
    return status;
}

int run_headless_replay(const CommandLine& command_line) {
    const std::string& path = *command_line.replay_path;
    std::string error;
    std::optional<app::SessionRecord> record = app::read_session_file(path, error);
    if (!record) {
        std::fprintf(stderr, "error: %s\n", error.c_str());
        return exit_bad_input;
    }
    std::ofstream dump;
    if (!open_dump(command_line, dump)) return exit_bad_input;
    SceneLoadResult scene = load_scene_text(record->scene_toml, path);  // checked when read
    app::DemoState state(path, {}, *scene.scene);
    state.start_replay(*record);
    while (!state.replay_finished()) state.step(4096);
    const bool matches = state.replay_matches();
    std::printf(
        "replayed %s and %s of %s: final state hash %016llx %s\n",
        app::counted(static_cast<long long>(state.steps_run), "step", "steps").c_str(),
        app::counted(static_cast<long long>(record->events.size()), "event", "events").c_str(),
        path.c_str(), static_cast<unsigned long long>(hash_state(state.simulation.cloth())),
        matches ? "matches the recording" : "DIFFERS from the recording");
    if (!write_outputs(command_line, dump, state.simulation)) return exit_bad_input;
    return matches ? exit_ok : exit_replay_differs;
}

}  // namespace weft
