#include "replay_study.h"

#include <cstdio>
#include <filesystem>

#include "app/demo_state.h"
#include "app/session_record.h"
#include "app/status_text.h"
#include "csv_file.h"
#include "sim/core/energy.h"
#include "sim/guards/divergence.h"
#include "sim/scene_io/scene_loader.h"
#include "sim/scene_io/scene_writer.h"
#include "study.h"

namespace weft::bench {
namespace {

// The scene text with its integrator replaced (dt and everything else as recorded).
std::string with_integrator(const std::string& scene_toml, Integrator integrator) {
    SceneLoadResult loaded = load_scene_text(scene_toml, "recorded scene");
    loaded.scene->solver.integrator = integrator;  // the recording was checked when read
    return scene_to_toml(*loaded.scene);
}

}  // namespace

int run_replay_study(const ReplayOptions& options) {
    std::string error;
    std::optional<app::SessionRecord> record = app::read_session_file(options.session_path, error);
    if (!record) {
        std::fprintf(stderr, "error: %s\n", error.c_str());
        return 2;
    }
    std::filesystem::create_directories(options.out_dir);
    const std::string csv_path = options.out_dir + "/replay.csv";
    // With each run's step profile (step_profile.h): seconds in each phase, over all steps.
    CsvFile csv(csv_path,
                {"integrator",      "recorded",        "matches_recording", "recoveries",
                 "final_dt_s",      "final_energy_J",  "largest_stretch",   "cpu_seconds",
                 "steps",           "held_steps",      "integrate_s",       "implicit_setup_s",
                 "coarse_levels_s", "cg_iterations_s", "split_checks_s",    "strain_limit_s",
                 "contacts_s",      "tearing_s",       "guards_s",          "force_evaluations",
                 "cg_iterations",   "splits"});
    if (!csv.is_open()) {
        std::fprintf(stderr, "error: %s: cannot write\n", csv_path.c_str());
        return 2;
    }
    const SceneLoadResult recorded_scene = load_scene_text(record->scene_toml, "recorded scene");
    const Integrator recorded = recorded_scene.scene->solver.integrator;
    std::printf(
        "weft-bench replay on %s\n%s: %s, %s, recorded with %s\n", machine_description().c_str(),
        options.session_path.c_str(),
        app::counted(static_cast<long long>(record->steps), "step", "steps").c_str(),
        app::counted(static_cast<long long>(record->events.size()), "event", "events").c_str(),
        integrator_name(recorded));
    int status = 0;
    for (Integrator integrator : all_integrators) {
        if (stop_requested) break;
        app::SessionRecord run = *record;
        run.scene_toml = with_integrator(record->scene_toml, integrator);
        // The session's own changes of integrator become changes to this one.
        for (app::TimedEvent& timed : run.events) {
            for (SceneEdit& edit : timed.event.edits)
                if (edit.key == SceneKey::integrator) edit.value = integrator;
            if (timed.event.scene) {  // a format-1 recording's whole scene
                auto scene = std::make_shared<Scene>(*timed.event.scene);
                scene->solver.integrator = integrator;
                timed.event.scene = std::move(scene);
            }
        }
        std::printf("  %-17s ", integrator_name(integrator));
        std::fflush(stdout);
        const SceneLoadResult scene = load_scene_text(run.scene_toml, "replayed scene");
        app::DemoState state(options.session_path, {}, *scene.scene);
        state.main_run().recovery.profiling = true;
        state.start_replay(run);
        const double seconds = seconds_of([&] {
            while (!state.replay_finished() && !stop_requested) state.step(4096);
        });
        const bool matches = state.replay_matches();
        const StepProfile& profile = state.main_run().recovery.profile;
        const double energy =
            measure_energy(state.simulation().cloth(), state.simulation().force_field()).total();
        const double stretch = largest_stretch_ratio(state.simulation().cloth());
        std::printf(
            "%s%s, ends at dt %.3g ms, energy %.4g J, largest stretch %.3f, "
            "%.3g s CPU\n",
            integrator == recorded ? (matches ? "(recorded: reproduced bit for bit) "
                                              : "(recorded: DIFFERS from the recording) ")
                                   : "",
            app::counted(state.main_run().recovery.recoveries, "recovery", "recoveries").c_str(),
            state.simulation().dt() * 1e3, energy, stretch, seconds);
        csv.write_row({integrator_name(integrator),
                       integrator == recorded ? "yes" : "no",
                       integrator == recorded ? (matches ? "yes" : "no") : "",
                       std::to_string(state.main_run().recovery.recoveries),
                       cell(state.simulation().dt()),
                       cell(energy),
                       cell(stretch),
                       cell(seconds),
                       std::to_string(profile.steps),
                       std::to_string(profile.held_steps),
                       cell(profile.seconds.integrate),
                       cell(profile.seconds.implicit.setup),
                       cell(profile.seconds.implicit.coarse_levels),
                       cell(profile.seconds.implicit.iterations),
                       cell(profile.seconds.implicit.split_checks),
                       cell(profile.seconds.strain_limit),
                       cell(profile.seconds.contacts),
                       cell(profile.seconds.tearing),
                       cell(profile.seconds.guards),
                       std::to_string(profile.force_evaluations),
                       std::to_string(profile.solver_iterations),
                       std::to_string(profile.splits)});
        if (integrator == recorded && !matches) status = 4;
    }
    std::printf("wrote %s\n", csv_path.c_str());
    return stop_requested ? 130 : status;
}

}  // namespace weft::bench
