#include "precision_study.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <map>

#include "csv_file.h"
#include "invariant_study.h"
#include "plot.h"
#include "sim/core/energy.h"
#include "study.h"

namespace weft::bench {
namespace {

// The error is measured at four times, every `steps_per_sample_at_base` steps of the scene's
// own dt. The ladder's steps are the scene's dt times these factors; all divide the sample
// interval exactly, so every run lands on the sample times.
constexpr int sample_count = 4;
constexpr long long steps_per_sample_at_base = 128;
constexpr double ladder_factors[] = {2.0, 1.0, 0.5, 0.25, 0.125, 0.0625};
constexpr double reference_factor = 1.0 / 64.0;  // checked against 1/128

struct Trajectory {
    std::vector<std::vector<Vec3>> samples;  // positions at each sample time
    double final_energy = 0.0;               // J
    bool diverged = false;
};

Trajectory simulate(const Scene& scene, Integrator integrator, double dt, double sample_interval) {
    Scene run_scene = scene;
    run_scene.solver = {integrator, dt};
    Simulation simulation(run_scene);
    Trajectory trajectory;
    const long long steps = std::llround(sample_interval / dt);
    for (int s = 0; s < sample_count && !trajectory.diverged; ++s) {
        trajectory.diverged = !run_steps(simulation, steps);
        trajectory.samples.push_back(simulation.cloth().positions);
    }
    trajectory.final_energy = measure_energy(simulation.cloth(), simulation.force_field()).total();
    return trajectory;
}

struct Errors {
    double rms = 0.0;  // m, largest over the sample times of the RMS over particles
    double max = 0.0;  // m, largest over sample times and particles
};

Errors errors_between(const Trajectory& run, const Trajectory& reference) {
    Errors errors;
    for (int s = 0; s < sample_count; ++s) {
        double sum_squares = 0.0;
        const std::vector<Vec3>& x = run.samples[s];
        for (std::size_t p = 0; p < x.size(); ++p) {
            const double e = glm::length(x[p] - reference.samples[s][p]);
            sum_squares += e * e;
            errors.max = std::max(errors.max, e);
        }
        errors.rms = std::max(errors.rms, std::sqrt(sum_squares / static_cast<double>(x.size())));
    }
    return errors;
}

// The trajectory-error study proper, on scenes whose trajectories are smooth.
int run_trajectory_study(const PrecisionOptions& options) {
    std::filesystem::create_directories(options.out_dir);
    const std::string csv_path = options.out_dir + "/precision.csv";
    CsvFile csv(csv_path, {"scene", "integrator", "dt_s", "steps", "diverged", "rms_error_m",
                           "max_error_m", "force_evaluations", "seconds_per_simulated_second",
                           "energy_error_J", "reference_agreement_m"});
    if (!csv.is_open()) {
        std::fprintf(stderr, "error: %s: cannot write\n", csv_path.c_str());
        return 2;
    }
    std::printf("weft-bench precision on %s\n", machine_description().c_str());

    for (const std::string& scene_path : options.scenes) {
        std::string error;
        auto scene = load_study_scene(scene_path, options.overrides, error);
        if (!scene) {
            std::fprintf(stderr, "%s\n", error.c_str());
            return 2;
        }
        const std::string tag = std::filesystem::path(scene_path).stem().string();
        const double base_dt = scene->solver.dt;
        const double sample_interval = steps_per_sample_at_base * base_dt;
        std::printf("\n%s: %d x %d particles, T = %g s, error sampled every %g s\n", tag.c_str(),
                    scene->cloth.rows, scene->cloth.cols, sample_count * sample_interval,
                    sample_interval);

        // The reference, and proof that it has converged: two RK4 runs a factor 2 apart.
        std::printf("  reference: rk4 at dt = %g s and %g s ...\n", base_dt * reference_factor,
                    base_dt * reference_factor / 2);
        std::fflush(stdout);
        const Trajectory reference =
            simulate(*scene, Integrator::rk4, base_dt * reference_factor, sample_interval);
        const Trajectory check =
            simulate(*scene, Integrator::rk4, base_dt * reference_factor / 2, sample_interval);
        const double reference_agreement = errors_between(reference, check).max;
        std::printf("  reference agreement (max over particles and times): %.3g m\n",
                    reference_agreement);

        PlotSpec work{
            "Work-precision: " + scene->name + " (" + tag + ")",
            "CPU seconds per simulated second (median of " + std::to_string(options.repeats) + ")",
            "RMS position error, max over 4 times (m)"};
        PlotSpec order{"Error against dt: " + scene->name + " (" + tag + ")", "dt (s)",
                       "RMS position error, max over 4 times (m)"};
        int colour = 0;
        for (Integrator integrator : all_integrators) {
            if (stop_requested) break;
            PlotSeries work_series{integrator_name(integrator), series_colour(colour)};
            PlotSeries order_series{integrator_name(integrator), series_colour(colour)};
            ++colour;
            std::vector<double> fit_dt, fit_error;
            std::string diverged_steps;  // the steps at which this integrator diverged
            for (double factor : ladder_factors) {
                if (stop_requested) break;
                const double dt = base_dt * factor;
                const long long steps = sample_count * std::llround(sample_interval / dt);
                std::printf("  %-17s dt = %-10g ", integrator_name(integrator), dt);
                std::fflush(stdout);
                Trajectory run;
                const double first =
                    seconds_of([&] { run = simulate(*scene, integrator, dt, sample_interval); });
                // The run that recorded the trajectory is the first timing; --repeats 1 is
                // that run alone, with no further runs to take a median of.
                const double seconds =
                    run.diverged || options.repeats < 2
                        ? first
                        : std::min(first, median_seconds(options.repeats - 1, [&] {
                                       simulate(*scene, integrator, dt, sample_interval);
                                   }));
                const double per_simulated_second = seconds / (sample_count * sample_interval);
                const Errors errors =
                    run.diverged ? Errors{NAN, NAN} : errors_between(run, reference);
                const double evaluations =
                    static_cast<double>(steps) * force_evaluations_per_step(integrator);
                csv.write_row({tag, integrator_name(integrator), cell(dt), std::to_string(steps),
                               run.diverged ? "yes" : "no", cell(errors.rms), cell(errors.max),
                               cell(evaluations), cell(per_simulated_second),
                               cell(run.diverged ? NAN : run.final_energy - reference.final_energy),
                               cell(reference_agreement)});
                if (run.diverged) {
                    std::printf("diverged\n");
                    diverged_steps += (diverged_steps.empty() ? "" : " ") + cell(dt);
                    continue;
                }
                std::printf("rms %.3e m  max %.3e m  %.3g s/s\n", errors.rms, errors.max,
                            per_simulated_second);
                work_series.points.push_back({per_simulated_second, errors.rms});
                order_series.points.push_back({dt, errors.rms});
                // Fit the order only where the error stands well above the reference's own.
                if (errors.max > 100.0 * reference_agreement)
                    fit_dt.push_back(dt), fit_error.push_back(errors.rms);
            }
            if (fit_dt.size() >= 2) {
                const double fitted = fitted_log_slope(fit_dt, fit_error);
                char label[80];
                std::snprintf(label, sizeof label, "%s (order %.2f)", integrator_name(integrator),
                              fitted);
                order_series.label = label;
                std::printf("  %-17s fitted order %.2f over %zu points\n",
                            integrator_name(integrator), fitted, fit_dt.size());
            }
            if (!diverged_steps.empty()) {
                work.notes.push_back(std::string(integrator_name(integrator)) + " diverged at dt:");
                work.notes.push_back("  " + diverged_steps);
            }
            work.series.push_back(work_series);
            order.series.push_back(order_series);
        }
        order.notes.push_back("reference: rk4, agreement " + cell(reference_agreement) + " m");
        std::string plot_error;
        for (auto& [spec, name] : {std::pair{&work, "work"}, std::pair{&order, "order"}}) {
            const std::string path = options.out_dir + "/precision_" + tag + "_" + name + ".png";
            if (!write_plot_png(*spec, path, &plot_error))
                std::fprintf(stderr, "error: %s: %s\n", path.c_str(), plot_error.c_str());
        }
        if (stop_requested) break;
    }
    std::printf("\nwrote %s and its plots\n", csv_path.c_str());
    return stop_requested ? 130 : 0;
}

}  // namespace

int run_precision_study(const PrecisionOptions& options) {
    // A scene with tears or contacts has no trajectory to converge to (a discontinuity parts
    // two runs for good), so its runs are measured by their invariants instead.
    PrecisionOptions smooth = options;
    InvariantOptions rough{
        {}, options.overrides, options.out_dir, options.repeats, options.invariant_duration};
    smooth.scenes.clear();
    for (const std::string& path : options.scenes) {
        std::string error;
        auto scene = load_study_scene(path, options.overrides, error);
        if (!scene) {
            std::fprintf(stderr, "%s\n", error.c_str());
            return 2;
        }
        if (has_discontinuities(*scene)) {
            std::printf("%s: tearing or contacts, so invariants instead of trajectory errors\n",
                        path.c_str());
            rough.scenes.push_back(path);
        } else {
            smooth.scenes.push_back(path);
        }
    }
    if (!smooth.scenes.empty()) {
        if (const int status = run_trajectory_study(smooth); status != 0) return status;
    }
    if (!rough.scenes.empty()) return run_invariant_study(rough);
    return 0;
}

}  // namespace weft::bench
