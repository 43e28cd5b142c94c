#include "app/headless_runner.h"

#include "app/profile_text.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <optional>
#include <span>
#include <vector>

#include "app/demo_state.h"
#include "app/obj_export.h"
#include "app/profile_text.h"
#include "app/session_record.h"
#include "app/side_by_side.h"
#include "app/state_dump.h"
#include "app/status_text.h"
#include "raster/png_writer.h"
#include "sim/core/energy.h"
#include "sim/core/simulation.h"
#include "sim/core/state_hash.h"
#include "sim/scene_io/scene_loader.h"
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

// The files a run writes at its end, opened before it starts so that an unwritable path
// fails at once, not after the run.
struct OutputFiles {
    std::ofstream dump;
    std::ofstream obj;
};

bool open_output(const std::optional<std::string>& path, std::ofstream& file) {
    if (!path) return true;
    file.open(*path, std::ios::binary | std::ios::trunc);
    if (file) return true;
    print_error(*path, std::string("cannot write: ") + std::strerror(errno));
    return false;
}

bool open_outputs(const CommandLine& command_line, OutputFiles& files) {
    return open_output(command_line.dump_path, files.dump) &&
           open_output(command_line.obj_path, files.obj);
}

// The runs side by side in equal columns of a `width` x `height` image, over the ground grid
// at `ground_height` (m), seen through the main run's scene camera.
raster::Framebuffer draw_runs(std::span<const Simulation* const> runs, int width, int height,
                              float ground_height, WorkerPool& pool) {
    raster::Framebuffer framebuffer(width, height);
    std::vector<view::ClothView> cloth_views;
    cloth_views.reserve(runs.size());
    std::vector<app::RunView> columns;
    for (const Simulation* run : runs) {
        cloth_views.emplace_back(run->cloth());
        columns.push_back({run, &cloth_views.back()});
    }
    std::vector<raster::Framebuffer> scratch;
    const int column_width = std::max(1, width / static_cast<int>(runs.size()));
    app::render_columns(framebuffer, scratch, view::scene_camera(runs[0]->scene()), columns,
                        column_width, view::FrameOptions{}, ground_height, &pool);
    return framebuffer;
}

// Writes the dump and the OBJ file (of the main run, runs[0]) and the screenshot asked for,
// the runs side by side, over the ground grid at `ground_height` (m); false (after saying
// why) if one fails.
bool write_outputs(const CommandLine& command_line, OutputFiles& files,
                   std::span<const Simulation* const> runs, float ground_height) {
    const Simulation& simulation = *runs[0];
    // Writes into `file`, if it was asked for, what `write` writes; false after saying why.
    auto finish = [](std::ofstream& file, const std::optional<std::string>& path, auto write) {
        if (!file.is_open()) return true;
        write(file);
        file.flush();
        if (file) return true;
        print_error(*path, "write failed");
        return false;
    };
    if (!finish(files.dump, command_line.dump_path,
                [&](std::ostream& out) { write_state_csv(simulation.cloth(), out); }) ||
        !finish(files.obj, command_line.obj_path, [&](std::ostream& out) {
            app::write_cloth_obj(simulation.cloth(), simulation.scene().name, out);
        }))
        return false;
    if (command_line.screenshot_path) {
        WorkerPool pool(default_thread_count());  // bands: the same image on any count
        const raster::Framebuffer framebuffer =
            draw_runs(runs, command_line.screenshot_width, command_line.screenshot_height,
                      ground_height, pool);
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
struct Copy {
    Simulation simulation;
    bool stopped = false;  // diverged, and left where it was caught
};

std::vector<Copy> comparison_runs(const Scene& scene, const CommandLine& command_line) {
    std::vector<Copy> copies;
    for (const CommandLine::Comparison& comparison : command_line.comparisons) {
        Scene copy = scene;
        copy.solver.integrator = *integrator_from_name(comparison.integrator);
        if (comparison.dt > 0.0) copy.solver.dt = comparison.dt;
        copies.push_back({Simulation(copy)});
    }
    return copies;
}

// Steps each copy with its own dt to the simulated time `time` (s); one that diverges stops
// where it was caught and says so, once.
void catch_up(std::vector<Copy>& copies, double time) {
    for (Copy& copy : copies) {
        Simulation& run = copy.simulation;
        while (!copy.stopped && run.time() + 0.5 * run.dt() <= time) {
            StepReport report = run.step();
            if (report.diverged()) {
                std::fprintf(stderr, "note: the %s copy diverged at t=%.6g s: %s\n",
                             integrator_name(run.integrator()), run.time(),
                             report.divergence->c_str());
                copy.stopped = true;
            }
        }
    }
}

std::vector<const Simulation*> runs_of(const Simulation& main, const std::vector<Copy>& copies) {
    std::vector<const Simulation*> runs{&main};
    for (const Copy& copy : copies) runs.push_back(&copy.simulation);
    return runs;
}

// --frames DIR: frame k, DIR/frame-KKKKK.png, shows the runs at k/fps s of simulated time (the
// nearest step), over a ground grid that stays where it started, so the frames make a video.
class FrameWriter {
  public:
    FrameWriter(const CommandLine& command_line, float ground_height)
        : directory_(*command_line.frames_dir),
          frames_per_second_(command_line.frames_per_second),
          width_(command_line.screenshot_width),
          height_(command_line.screenshot_height),
          ground_height_(ground_height) {}

    // Creates the folder; false (after saying why) if it cannot be.
    bool open() {
        std::error_code error;
        std::filesystem::create_directories(directory_, error);
        if (error || !std::filesystem::is_directory(directory_)) {
            print_error(directory_, "cannot make the frames' folder: " +
                                        (error ? error.message() : std::string("not a folder")));
            return false;
        }
        return true;
    }

    // Writes every frame due by the main run's time, the copies caught up first; false (after
    // saying why) if one cannot be written.
    bool write_due(const Simulation& main, std::vector<Copy>& copies) {
        while (due(main)) {
            catch_up(copies, main.time());
            if (!write(runs_of(main, copies))) return false;
        }
        return true;
    }

    // The same for a replay, whose copies step with the main run (runs[0]).
    bool write_due(const std::vector<const Simulation*>& runs) {
        while (due(*runs[0]))
            if (!write(runs)) return false;
        return true;
    }

  private:
    bool due(const Simulation& main) const {
        return static_cast<double>(next_) / frames_per_second_ <= main.time() + 0.5 * main.dt();
    }

    // The next frame: the runs side by side.
    bool write(const std::vector<const Simulation*>& runs) {
        const raster::Framebuffer frame = draw_runs(runs, width_, height_, ground_height_, pool_);
        char name[32];
        std::snprintf(name, sizeof name, "frame-%05llu.png", next_);
        const std::string path = (std::filesystem::path(directory_) / name).string();
        std::string error;
        if (!raster::write_png(frame, path, &error)) {
            print_error(path, error);
            return false;
        }
        ++next_;
        return true;
    }

    std::string directory_;
    int frames_per_second_;
    int width_, height_;
    float ground_height_;
    unsigned long long next_ = 0;              // the next frame's number
    WorkerPool pool_{default_thread_count()};  // bands: the same image on any count
};

}  // namespace

int run_headless(const CommandLine& command_line) {
    std::optional<Scene> scene =
        load_checked_scene(*command_line.scene_path, command_line.overrides);
    if (!scene) return exit_bad_input;
    OutputFiles files;
    if (!open_outputs(command_line, files)) return exit_bad_input;

    Simulation simulation(*scene);
    const float start_ground_height =
        view::ground_height_below(simulation.cloth(), simulation.colliders());
    std::optional<FrameWriter> frames;
    if (command_line.frames_dir) {
        frames.emplace(command_line, start_ground_height);
        if (!frames->open()) return exit_bad_input;
    }
    // Copies only to be drawn: each follows the main run to the same simulated time with its
    // own dt.
    std::vector<Copy> copies;
    if (command_line.screenshot_path || frames) copies = comparison_runs(*scene, command_line);
    if (frames && !frames->write_due(simulation, copies)) return exit_bad_input;
    int status = exit_ok;
    StepProfile profile;
    simulation.set_profiling(command_line.profile);
    for (std::uint64_t step = 0; step < *command_line.steps; ++step) {
        const std::uint64_t evaluations_before = simulation.force_evaluations();
        StepReport report = simulation.step();
        if (command_line.profile)
            profile.add(report.times, report.held, report.hand_slipped,
                        simulation.force_evaluations() - evaluations_before,
                        simulation.last_linear_solve().iterations, simulation.last_step_splits(),
                        simulation.last_step_newton_iterations(),
                        simulation.last_step_tries_stopped_early());
        if (report.diverged()) {
            print_divergence(simulation, *report.divergence, step + 1, *command_line.steps);
            status = exit_diverged;
            break;
        }
        if (frames && !frames->write_due(simulation, copies)) return exit_bad_input;
    }
    catch_up(copies, simulation.time());
    if (command_line.profile)
        std::fputs(app::profile_text(profile, simulation.dt(), simulation.thread_count()).c_str(),
                   stdout);
    // Also written on divergence: the state that was caught is what one wants to look at.
    if (!write_outputs(command_line, files, runs_of(simulation, copies),
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
    OutputFiles files;
    if (!open_outputs(command_line, files)) return exit_bad_input;
    SceneLoadResult scene = load_scene_text(record->scene_toml, path);  // checked when read
    app::DemoState state(path, {}, *scene.scene);
    for (const CommandLine::Comparison& comparison : command_line.comparisons)
        state.add_copy(*integrator_from_name(comparison.integrator),
                       comparison.dt > 0.0 ? comparison.dt : scene.scene->solver.dt);
    state.main_run().recovery.profiling = command_line.profile;
    state.start_replay(*record);
    std::optional<FrameWriter> frames;
    auto runs_now = [&] {
        std::vector<const Simulation*> runs;
        for (int run = 0; run < state.run_count(); ++run) runs.push_back(&state.run(run));
        return runs;
    };
    if (command_line.frames_dir) {
        frames.emplace(command_line, state.ground_height);
        if (!frames->open() || !frames->write_due(runs_now())) return exit_bad_input;
    }
    // With frames, a step at a time so that each is drawn at its own time.
    while (!state.replay_finished()) {
        state.step(frames ? 1 : 4096);
        if (frames && !frames->write_due(runs_now())) return exit_bad_input;
    }
    const bool matches = state.replay_matches();
    std::printf(
        "replayed %s and %s of %s: final state hash %016llx %s\n",
        app::counted(static_cast<long long>(state.steps_run), "step", "steps").c_str(),
        app::counted(static_cast<long long>(record->events.size()), "event", "events").c_str(),
        path.c_str(), static_cast<unsigned long long>(hash_state(state.simulation().cloth())),
        matches ? "matches the recording" : "DIFFERS from the recording");
    if (command_line.profile)
        std::fputs(app::profile_text(state.main_run().recovery.profile, state.simulation().dt(),
                                     state.simulation().thread_count())
                       .c_str(),
                   stdout);
    if (!write_outputs(command_line, files, runs_now(),
                       final_ground_height(state.simulation(), state.ground_height)))
        return exit_bad_input;
    return matches ? exit_ok : exit_replay_differs;
}

}  // namespace weft
