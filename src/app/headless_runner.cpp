#include "app/headless_runner.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <glm/geometric.hpp>
#include <optional>
#include <span>
#include <vector>

#include "app/demo_state.h"
#include "app/session_record.h"
#include "app/side_by_side.h"
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

// Writes the dump (of the main run, runs[0]) and the screenshot asked for, the runs side by
// side in equal columns, over the ground grid at `ground_height` (m); false (after saying
// why) if one fails.
bool write_outputs(const CommandLine& command_line, std::ofstream& dump,
                   std::span<const Simulation* const> runs, float ground_height) {
    const Simulation& simulation = *runs[0];
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
        std::vector<view::ClothView> cloth_views;
        cloth_views.reserve(runs.size());
        std::vector<app::RunView> columns;
        for (const Simulation* run : runs) {
            cloth_views.emplace_back(run->cloth());
            columns.push_back({run, &cloth_views.back()});
        }
        WorkerPool pool(default_thread_count());  // bands: the same image on any count
        std::vector<raster::Framebuffer> scratch;
        const int column_width =
            std::max(1, command_line.screenshot_width / static_cast<int>(runs.size()));
        app::render_columns(framebuffer, scratch, view::scene_camera(simulation.scene()), columns,
                            column_width, view::FrameOptions{}, ground_height, &pool);
        std::string error;
        if (!raster::write_png(framebuffer, *command_line.screenshot_path, &error)) {
            print_error(*command_line.screenshot_path, error);
            return false;
        }
    }
    return true;
}

// Where the screenshot's ground grid goes: below the cloth as it ends, but never more than the
// cloth's length below where the grid was as it started: a piece torn off and falling away
// would otherwise take the ground out of the picture.
float final_ground_height(const Simulation& simulation, float start_ground_height) {
    const Cloth& cloth = simulation.cloth();
    const auto cloth_length = static_cast<float>(cloth.rest_span());  // m
    return std::max(view::ground_height_below(cloth, simulation.colliders()),
                    start_ground_height - cloth_length);
}

// The copies --compare asks for: the scene with another integrator (and dt).
std::vector<Simulation> comparison_runs(const Scene& scene, const CommandLine& command_line) {
    std::vector<Simulation> copies;
    for (const CommandLine::Comparison& comparison : command_line.comparisons) {
        Scene copy = scene;
        copy.solver.integrator = *integrator_from_name(comparison.integrator);
        if (comparison.dt > 0.0) copy.solver.dt = comparison.dt;
        copies.emplace_back(copy);
    }
    return copies;
}

}  // namespace

int run_headless(const CommandLine& command_line) {
    std::optional<Scene> scene =
        load_checked_scene(*command_line.scene_path, command_line.overrides);
    if (!scene) return exit_bad_input;
    std::ofstream dump;
    if (!open_dump(command_line, dump)) return exit_bad_input;

    Simulation simulation(*scene);
    const float start_ground_height =
        view::ground_height_below(simulation.cloth(), simulation.colliders());
    int status = exit_ok;
    for (std::uint64_t step = 0; step < *command_line.steps; ++step) {
        StepReport report = simulation.step();
        if (report.diverged()) {
            print_divergence(simulation, *report.divergence, step + 1, *command_line.steps);
            status = exit_diverged;
            break;
        }
    }
    // Copies for the screenshot only: each follows the main run to the same simulated time
    // with its own dt; one that diverges stops where it was caught and says so.
    std::vector<Simulation> copies;
    if (command_line.screenshot_path) copies = comparison_runs(*scene, command_line);
    for (Simulation& copy : copies) {
        while (copy.time() + 0.5 * copy.dt() <= simulation.time()) {
            StepReport report = copy.step();
            if (report.diverged()) {
                std::fprintf(stderr, "note: the %s copy diverged at t=%.6g s: %s\n",
                             integrator_name(copy.integrator()), copy.time(),
                             report.divergence->c_str());
                break;
            }
        }
    }
    std::vector<const Simulation*> runs{&simulation};
    for (const Simulation& copy : copies) runs.push_back(&copy);
    // Also written on divergence: the state that was caught is what one wants to look at.
    if (!write_outputs(command_line, dump, runs,
                       final_ground_height(simulation, start_ground_height)))
        return exit_bad_input;
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
    for (const CommandLine::Comparison& comparison : command_line.comparisons)
        state.add_companion(*integrator_from_name(comparison.integrator),
                            comparison.dt > 0.0 ? comparison.dt : scene.scene->solver.dt);
    state.start_replay(*record);
    while (!state.replay_finished()) state.step(4096);
    const bool matches = state.replay_matches();
    std::printf(
        "replayed %s and %s of %s: final state hash %016llx %s\n",
        app::counted(static_cast<long long>(state.steps_run), "step", "steps").c_str(),
        app::counted(static_cast<long long>(record->events.size()), "event", "events").c_str(),
        path.c_str(), static_cast<unsigned long long>(hash_state(state.simulation.cloth())),
        matches ? "matches the recording" : "DIFFERS from the recording");
    std::vector<const Simulation*> runs;
    for (int run = 0; run < state.run_count(); ++run) runs.push_back(&state.run(run));
    if (!write_outputs(command_line, dump, runs,
                       final_ground_height(state.simulation, state.ground_height)))
        return exit_bad_input;
    return matches ? exit_ok : exit_replay_differs;
}

}  // namespace weft
