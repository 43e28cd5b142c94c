#include "stability_study.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <random>

#include "csv_file.h"
#include "plot.h"
#include "sim/build/cloth_builder.h"
#include "sim/core/energy.h"
#include "sim/guards/stability_limit.h"
#include "study.h"

namespace weft::bench {
namespace {

// A run longer than this many steps is not attempted: the step is reported as "below the
// range measured" instead of making a sweep take hours.
constexpr long long step_budget = 400'000;

struct SweepPoint {
    std::string label;  // e.g. "27x27"
    double value;       // the swept quantity
    Scene scene;
};

std::vector<SweepPoint> sweep_points(const std::string& sweep, const Scene& base) {
    std::vector<SweepPoint> points;
    if (sweep == "grid") {
        for (int n : {10, 15, 20, 27, 32, 48, 64}) {
            Scene scene = base;
            scene.cloth.rows = scene.cloth.cols = n;
            points.push_back(
                {std::to_string(n) + "x" + std::to_string(n), static_cast<double>(n), scene});
        }
    } else if (sweep == "mass") {
        for (double mass : {0.001, 0.003, 0.01, 0.03, 0.1}) {
            Scene scene = base;
            scene.cloth.particle_mass = mass;
            points.push_back({cell(mass) + " kg", mass, scene});
        }
    } else if (sweep == "stiffness") {
        // All families scale together, so the ratio between them stays the scene's.
        for (double structural : {100.0, 300.0, 1000.0, 3000.0, 10000.0, 30000.0}) {
            Scene scene = base;
            const double ratio = structural / base.structural.stiffness;
            scene.structural.stiffness = structural;
            scene.shear.stiffness *= ratio;
            scene.bend.stiffness *= ratio;
            points.push_back({cell(structural) + " N/m", structural, scene});
        }
    }
    return points;
}

// Undamped: the linear prediction is for the undamped system, and damping only widens the
// stable range of the symplectic methods (explicit Euler is measured with the scene's own).
Scene without_damping(Scene scene) {
    scene.structural.damping = scene.shear.damping = scene.bend.damping = 0.0;
    scene.forces.air_drag = 0.0;
    return scene;
}

struct RunResult {
    bool stable;
    double seconds;  // wall time of the run
};

// Stable over `duration`: no divergence (non-finite, 5x stretch) and no energy growth past
// ten times the energy that gravity can put into motion (the weight times the cloth's size).
// A tiny deterministic jitter excites every mode, the fastest included.
RunResult run_is_stable(const Scene& scene, Integrator integrator, double dt, double duration) {
    Scene run_scene = scene;
    run_scene.solver = {integrator, dt};
    Simulation simulation(run_scene);
    Cloth& cloth = simulation.edit_cloth();
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> jitter(-1e-6, 1e-6);
    for (Vec3& x : cloth.positions) x += Vec3(jitter(rng), jitter(rng), jitter(rng));
    const double weight = static_cast<double>(cloth.particle_count()) * scene.cloth.particle_mass *
                          glm::length(simulation.force_field().gravity);
    const double size = std::max(scene.cloth.rows, scene.cloth.cols) * scene.cloth.spacing;
    const double energy_bound = std::abs(measure_energy(cloth, simulation.force_field()).total()) +
                                10.0 * weight * size + 1e-9;
    const long long steps = std::llround(duration / dt);
    bool stable = true;
    const double seconds = seconds_of([&] {
        for (long long s = 0; s < steps && stable; ++s) {
            if (simulation.step().diverged()) stable = false;
            if (s % 64 == 63 &&
                measure_energy(simulation.cloth(), simulation.force_field()).total() > energy_bound)
                stable = false;
        }
    });
    return {stable, seconds};
}

struct Limit {
    double dt = NAN;                            // s, largest stable step found (NaN: none in range)
    double seconds_per_simulated_second = NAN;  // cost of running at that step
    std::string note;                           // why a limit is missing
};

// Bisection on dt between a stable and an unstable step, to 1 % (geometric midpoints).
Limit measure_limit(const Scene& scene, Integrator integrator, double guess, double duration) {
    Limit limit;
    // An asymmetric bracket, so the first midpoint is not the prediction itself.
    double stable = guess / 3.0, unstable = guess * 5.0;
    RunResult at_stable{false, 0.0};
    while (true) {
        if (duration / stable > step_budget) {
            limit.note = "no stable step >= " + cell(stable * 2.0) + " s";
            return limit;
        }
        at_stable = run_is_stable(scene, integrator, stable, duration);
        if (at_stable.stable || stop_requested) break;
        unstable = stable;
        stable /= 2.0;
    }
    while (run_is_stable(scene, integrator, unstable, duration).stable && !stop_requested) {
        stable = unstable;
        unstable *= 2.0;
        if (unstable > 1.0) break;
    }
    while (unstable / stable > 1.01 && !stop_requested) {
        const double middle = std::sqrt(stable * unstable);
        RunResult result = run_is_stable(scene, integrator, middle, duration);
        if (result.stable) {
            stable = middle;
            at_stable = result;
        } else {
            unstable = middle;
        }
    }
    limit.dt = stable;
    limit.seconds_per_simulated_second =
        run_is_stable(scene, integrator, stable, duration).seconds / duration;
    return limit;
}

}  // namespace

int run_stability_study(const StabilityOptions& options) {
    std::string error;
    auto base = load_study_scene(options.scene, options.overrides, error);
    if (!base) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return 2;
    }
    std::filesystem::create_directories(options.out_dir);
    std::printf("weft-bench stability on %s: %s, stable = sound for %g s of simulated time\n",
                machine_description().c_str(), options.scene.c_str(), options.duration);
    for (const std::string& sweep : options.sweeps) {
        const std::string csv_path = options.out_dir + "/stability_" + sweep + ".csv";
        CsvFile csv(csv_path,
                    {"sweep", "point", "value", "integrator", "damping", "omega_max_rad_s",
                     "predicted_dt_s", "measured_dt_s", "measured_over_predicted",
                     "seconds_per_simulated_second_at_limit", "note"});
        if (!csv.is_open()) {
            std::fprintf(stderr, "error: %s: cannot write\n", csv_path.c_str());
            return 2;
        }
        const std::vector<SweepPoint> points = sweep_points(sweep, *base);
        if (points.empty()) {
            std::fprintf(stderr, "error: --sweep: unknown sweep '%s' (grid, mass or stiffness)\n",
                         sweep.c_str());
            return 2;
        }
        PlotSpec plot{"Largest stable dt against " + sweep + " (" +
                          std::filesystem::path(options.scene).stem().string() + ")",
                      sweep == "grid"   ? "particles per side"
                      : sweep == "mass" ? "particle mass (kg)"
                                        : "structural stiffness (N/m)",
                      "dt (s): measured (solid), predicted 2/w or 2.83/w (dashed)"};
        int colour = 0;
        for (Integrator integrator : explicit_integrators) {
            PlotSeries measured{std::string(integrator_name(integrator)), series_colour(colour)};
            PlotSeries predicted{std::string(integrator_name(integrator)) + " predicted",
                                 series_colour(colour),
                                 {},
                                 true,
                                 false};
            ++colour;
            // Explicit Euler has no stable step without damping; it is measured with the scene's.
            const bool damped = integrator == Integrator::explicit_euler;
            for (std::size_t k = 0; k < points.size() && !stop_requested; ++k) {
                const SweepPoint& point = points[k];
                const Scene scene = damped ? point.scene : without_damping(point.scene);
                const double omega = highest_angular_frequency(build_cloth(scene));
                const double predicted_dt = stable_step_limit(integrator, omega);
                std::printf("  %-9s %-12s %-17s w_max %8.1f rad/s  predicted %-10.4g ",
                            sweep.c_str(), point.label.c_str(), integrator_name(integrator), omega,
                            predicted_dt);
                std::fflush(stdout);
                const double guess =
                    damped ? stable_step_limit(Integrator::symplectic_euler, omega) : predicted_dt;
                const Limit limit = measure_limit(scene, integrator, guess, options.duration);
                std::printf("measured %-10.4g %s\n", limit.dt, limit.note.c_str());
                csv.write_row({sweep, point.label, cell(point.value), integrator_name(integrator),
                               damped ? "scene" : "none", cell(omega), cell(predicted_dt),
                               cell(limit.dt),
                               cell(predicted_dt > 0 ? limit.dt / predicted_dt : NAN),
                               cell(limit.seconds_per_simulated_second), limit.note});
                measured.points.push_back({point.value, limit.dt});
                if (predicted_dt > 0) predicted.points.push_back({point.value, predicted_dt});
            }
            plot.series.push_back(measured);
            if (!predicted.points.empty()) plot.series.push_back(predicted);
        }
        plot.notes = {"undamped; explicit-euler", "with the scene's damping"};
        const std::string path = options.out_dir + "/stability_" + sweep + ".png";
        if (!write_plot_png(plot, path, &error))
            std::fprintf(stderr, "error: %s: %s\n", path.c_str(), error.c_str());
        std::printf("wrote %s and %s\n", csv_path.c_str(), path.c_str());
        if (stop_requested) return 130;
    }
    return 0;
}

}  // namespace weft::bench
