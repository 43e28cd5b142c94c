#include "invariant_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <limits>

#include "app/status_text.h"
#include "csv_file.h"
#include "plot.h"
#include "sim/core/energy.h"
#include "sim/guards/divergence.h"
#include "study.h"

namespace weft::bench {
namespace {

// The same ladder as the precision study, so the two read side by side.
constexpr double ladder_factors[] = {2.0, 1.0, 0.5, 0.25, 0.125, 0.0625};
constexpr double finest_factor = 0.0625;  // the reference: RK4 at the finest step

// Largest |d|/L − 1 over the live springs (NaN when every spring has torn).
double largest_strain(const Cloth& cloth) {
    return largest_stretch_ratio(cloth) - 1.0;
}

// Height of the centre of mass (m): every particle has the same mass, so the mean height.
double centre_height(const Cloth& cloth) {
    double sum = 0.0;
    for (const Vec3& x : cloth.positions) sum += x.y;
    return cloth.particle_count() ? sum / static_cast<double>(cloth.particle_count()) : NAN;
}

struct Invariants {
    long long steps = 0;
    bool diverged = false;
    double diverged_at = NAN;      // s, simulated time of the step that diverged
    double energy_start = NAN;     // J, E(0)
    double energy_change = NAN;    // J, E(T) − E(0)
    double energy_max_rise = NAN;  // J, max over steps of E(t) − E(0) (0 if never above)
    double kinetic_end = NAN;      // J
    double strain_end = NAN;       // largest |d|/L − 1 at T
    double strain_run = NAN;       // largest |d|/L − 1 over every step
    double centre_drop = NAN;      // m, centre-of-mass height at 0 minus at T
    std::size_t torn = 0;          // springs torn (up to divergence)
    std::size_t contacts_end = 0;  // contacts resolved in the last step
    double contacts_per_step = NAN;
};

Simulation make_simulation(const Scene& scene, Integrator integrator, double dt) {
    Scene run_scene = scene;
    run_scene.solver = {integrator, dt};
    return Simulation(run_scene);
}

// One run, measuring after every step. Diverged runs keep only the step and the tear count.
Invariants measure(const Scene& scene, Integrator integrator, double dt, long long steps) {
    Simulation simulation = make_simulation(scene, integrator, dt);
    Invariants result;
    result.steps = steps;
    const double height_start = centre_height(simulation.cloth());
    result.energy_start = measure_energy(simulation.cloth(), simulation.force_field()).total();
    double max_rise = 0.0, strain_run = largest_strain(simulation.cloth());
    std::size_t contacts = 0;
    StepReport report;
    for (long long s = 0; s < steps; ++s) {
        report = simulation.step();
        result.torn += report.springs_torn;
        if (report.diverged()) {
            result.diverged = true;
            result.diverged_at = simulation.time();
            return result;
        }
        contacts += report.contacts;
        const double energy = measure_energy(simulation.cloth(), simulation.force_field()).total();
        max_rise = std::max(max_rise, energy - result.energy_start);
        strain_run = std::max(strain_run, largest_strain(simulation.cloth()));
    }
    const Energy end = measure_energy(simulation.cloth(), simulation.force_field());
    result.energy_change = end.total() - result.energy_start;
    result.energy_max_rise = max_rise;
    result.kinetic_end = end.kinetic;
    result.strain_end = largest_strain(simulation.cloth());
    result.strain_run = strain_run;
    result.centre_drop = height_start - centre_height(simulation.cloth());
    result.contacts_end = report.contacts;
    result.contacts_per_step = static_cast<double>(contacts) / static_cast<double>(steps);
    return result;
}

struct ScenePlots {
    PlotSpec strain, energy, sag;
};

ScenePlots make_plots(const std::string& title, double duration) {
    const std::string over = " over " + cell(duration) + " s";
    return {{"Largest strain: " + title, "dt (s)",
             "largest strain, max over springs and steps of |d|/L - 1" + over},
            {"Energy budget: " + title, "dt (s)",
             "E(T) - E(0) (J), E = kinetic + gravity + elastic" + over, true, false},
            {"Sag: " + title, "dt (s)", "drop of the centre of mass (m)" + over, true, false}};
}

// A dashed line across the ladder at the reference's value.
PlotSeries reference_line(double value, double dt_low, double dt_high) {
    return {"rk4 reference", {90, 90, 90, 255}, {{dt_low, value}, {dt_high, value}}, true, false};
}

}  // namespace

bool has_discontinuities(const Scene& scene) {
    return scene.tear_max_stretch.has_value() || !scene.colliders.empty() ||
           scene.self_collision_thickness.has_value();
}

int run_invariant_study(const InvariantOptions& options) {
    std::filesystem::create_directories(options.out_dir);
    std::printf("weft-bench invariants on %s, %g s of simulated time per run\n",
                machine_description().c_str(), options.duration);

    for (const std::string& scene_path : options.scenes) {
        std::string error;
        auto scene = load_study_scene(scene_path, options.overrides, error);
        if (!scene) {
            std::fprintf(stderr, "%s\n", error.c_str());
            return 2;
        }
        const std::string tag = std::filesystem::path(scene_path).stem().string();
        const std::string csv_path = options.out_dir + "/invariants_" + tag + ".csv";
        CsvFile csv(csv_path,
                    {"scene", "integrator", "dt_s", "duration_s", "steps", "diverged",
                     "diverged_at_s", "energy_start_J", "energy_change_J", "energy_max_rise_J",
                     "kinetic_end_J", "largest_strain_end", "largest_strain_run", "centre_drop_m",
                     "centre_drop_minus_reference_m", "springs_torn", "contacts_end",
                     "contacts_per_step", "seconds_per_simulated_second"});
        if (!csv.is_open()) {
            std::fprintf(stderr, "error: %s: cannot write\n", csv_path.c_str());
            return 2;
        }
        const double base_dt = scene->solver.dt;
        std::printf("\n%s: %d x %d particles, dt ladder from %g s\n", tag.c_str(),
                    scene->cloth.rows, scene->cloth.cols, base_dt * ladder_factors[0]);

        auto write = [&](const char* integrator, double dt, const Invariants& r,
                         double reference_drop, double per_simulated_second) {
            csv.write_row({tag, integrator, cell(dt), cell(static_cast<double>(r.steps) * dt),
                           std::to_string(r.steps), r.diverged ? "yes" : "no", cell(r.diverged_at),
                           cell(r.energy_start), cell(r.energy_change), cell(r.energy_max_rise),
                           cell(r.kinetic_end), cell(r.strain_end), cell(r.strain_run),
                           cell(r.centre_drop), cell(r.centre_drop - reference_drop),
                           std::to_string(r.torn), std::to_string(r.contacts_end),
                           cell(r.contacts_per_step), cell(per_simulated_second)});
            if (r.diverged) {
                std::printf(
                    "diverged at t = %g s (%s torn)\n", r.diverged_at,
                    app::counted(static_cast<long long>(r.torn), "spring", "springs").c_str());
                return;
            }
            std::printf(
                "dE %+.4g J  rise %.3g J  strain %.4f (end %.4f)  drop %.4f m  torn %zu"
                "  contacts %zu  %.3g s/s\n",
                r.energy_change, r.energy_max_rise, r.strain_run, r.strain_end, r.centre_drop,
                r.torn, r.contacts_end, per_simulated_second);
        };

        // The reference: its values are the ones the ladder should approach.
        const double reference_dt = base_dt * finest_factor;
        std::printf("  %-17s dt = %-10g ", "rk4 (reference)", reference_dt);
        std::fflush(stdout);
        const Invariants reference =
            measure(*scene, Integrator::rk4, reference_dt,
                    std::max(1LL, std::llround(options.duration / reference_dt)));
        write("rk4-reference", reference_dt, reference, reference.centre_drop, NAN);

        ScenePlots plots = make_plots(scene->name + " (" + tag + ")", options.duration);
        int colour = 0;
        for (Integrator integrator : all_integrators) {
            if (stop_requested) break;
            PlotSeries strain{integrator_name(integrator), series_colour(colour)};
            PlotSeries energy = strain, sag = strain;
            ++colour;
            std::string diverged_steps;
            for (double factor : ladder_factors) {
                if (stop_requested) break;
                const double dt = base_dt * factor;
                const long long steps = std::max(1LL, std::llround(options.duration / dt));
                std::printf("  %-17s dt = %-10g ", integrator_name(integrator), dt);
                std::fflush(stdout);
                // The measured run is also the timing's warm-up. RK4 at the finest step is
                // the reference run itself (the runs are deterministic).
                const Invariants r = integrator == Integrator::rk4 && factor == finest_factor
                                         ? reference
                                         : measure(*scene, integrator, dt, steps);
                double per_simulated_second = NAN;
                if (!r.diverged) {
                    per_simulated_second = min_seconds(options.repeats,
                                                       [&] {
                                                           Simulation simulation = make_simulation(
                                                               *scene, integrator, dt);
                                                           run_steps(simulation, steps);
                                                       }) /
                                           (static_cast<double>(steps) * dt);
                    strain.points.push_back({dt, r.strain_run});
                    energy.points.push_back({dt, r.energy_change});
                    sag.points.push_back({dt, r.centre_drop});
                } else {
                    if (!diverged_steps.empty()) diverged_steps += ' ';
                    diverged_steps += cell(dt);
                }
                write(integrator_name(integrator), dt, r, reference.centre_drop,
                      per_simulated_second);
            }
            for (PlotSpec* plot : {&plots.strain, &plots.energy, &plots.sag}) {
                if (!diverged_steps.empty()) {
                    plot->notes.push_back(std::string(integrator_name(integrator)) +
                                          " diverged at dt:");
                    plot->notes.push_back("  " + diverged_steps);
                }
            }
            plots.strain.series.push_back(strain);
            plots.energy.series.push_back(energy);
            plots.sag.series.push_back(sag);
        }
        const double dt_low = base_dt * ladder_factors[std::size(ladder_factors) - 1];
        const double dt_high = base_dt * ladder_factors[0];
        if (!reference.diverged) {
            plots.strain.series.push_back(reference_line(reference.strain_run, dt_low, dt_high));
            plots.energy.series.push_back(reference_line(reference.energy_change, dt_low, dt_high));
            plots.sag.series.push_back(reference_line(reference.centre_drop, dt_low, dt_high));
        }
        for (auto& [spec, name] :
             {std::pair{&plots.strain, "strain"}, std::pair{&plots.energy, "energy"},
              std::pair{&plots.sag, "sag"}}) {
            const std::string path = options.out_dir + "/invariants_" + tag + "_" + name + ".png";
            std::string plot_error;
            if (!write_plot_png(*spec, path, &plot_error))
                std::fprintf(stderr, "error: %s: %s\n", path.c_str(), plot_error.c_str());
        }
        std::printf("wrote %s and its plots\n", csv_path.c_str());
        if (stop_requested) break;
    }
    return stop_requested ? 130 : 0;
}

}  // namespace weft::bench
