// Contents: the sheet at each size; running a method frame by frame; the errors; the study
// (reference, drawing, the weft-to-plain ratio, every method and setting, the summary).
#include "realtime_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>

#include <glm/geometric.hpp>

#include "csv_file.h"
#include "parallel/worker_pool.h"
#include "plain_baseline.h"
#include "plot.h"
#include "raster/framebuffer.h"
#include "sim/guards/stability_limit.h"
#include "study.h"
#include "view/frame_renderer.h"
#include "xpbd_cloth.h"

namespace weft::bench {
namespace {

constexpr double frame = 1.0 / 60.0;  // s, one frame at 60 fps: the budget and the step unit
constexpr double not_measured = std::numeric_limits<double>::quiet_NaN();

// The scene's sheet with n × n particles and the same physical sheet: as wide (spacing =
// side / (n - 1)), the same areal density (mass ∝ spacing²), the same stiffness per spring
// (a grid's stiffness per unit width is k whatever the spacing) and the same damping rates
// c/m and air_drag/m (both scaled with the mass, as large_rubber_sheet.toml was made from the
// default sheet). Tearing, strain limiting, self-collision and colliders are taken out: the
// methods are compared on the springs alone, which is all XPBD and the plain step model.
Scene resized_sheet(const Scene& base, int n) {
    Scene scene = base;
    // m, the longer side (a sheet of one column has no width)
    const double side = (std::max(base.cloth.cols, base.cloth.rows) - 1) * base.cloth.spacing;
    const double spacing = side / (n - 1);
    const double mass_ratio = (spacing / base.cloth.spacing) * (spacing / base.cloth.spacing);
    scene.cloth.spacing = spacing;
    scene.cloth.particle_mass = base.cloth.particle_mass * mass_ratio;
    for (SpringFamilySpec* family : {&scene.structural, &scene.shear, &scene.bend})
        family->damping *= mass_ratio;
    scene.forces.air_drag *= mass_ratio;
    // Listed pins go to the same place on the sheet.
    for (GridIndex& pin : scene.cloth.pin_list) {
        const auto rescale = [n](int index, int count) {
            return count > 1 ? static_cast<int>(std::lround(double(index) * (n - 1) / (count - 1)))
                             : 0;
        };
        pin = {rescale(pin.row, base.cloth.rows), rescale(pin.col, base.cloth.cols)};
    }
    scene.cloth.rows = scene.cloth.cols = n;
    scene.tear_max_stretch.reset();
    scene.strain_limit_max_strain.reset();
    scene.self_collision_thickness.reset();
    scene.colliders.clear();
    return scene;
}

// One method at one setting, stepped a frame at a time.
struct Stepper {
    std::string method;   // series name
    std::string setting;  // e.g. "dt 1/120 s", "10 substeps"
    double dt;            // s, one step or substep
    int steps_per_frame;
    int threads;
    std::function<bool()> advance_frame;  // one simulated frame; false if the method diverged
    std::function<bool()> is_finite;      // checked after each frame, outside the timing
    std::function<std::vector<Vec3>()> positions;
};

struct Outcome {
    double seconds_per_frame = not_measured;  // s of CPU per simulated frame, median
    int frames_run = 0;
    bool diverged = false;
    bool cut_short = false;       // stopped at max_run_seconds (or Ctrl-C): no error measured
    std::vector<Vec3> positions;  // at the end, if it got there soundly
};

// Runs `frames` frames, timing each with steady_clock; the cost is the median over frames
// after the first (a warm-up: caches, the implicit solver's allocation).
Outcome run_frames(const Stepper& stepper, int frames, double max_run_seconds) {
    Outcome outcome;
    std::vector<double> seconds;
    double total = 0.0;
    for (int f = 0; f < frames; ++f) {
        const auto start = std::chrono::steady_clock::now();
        const bool sound = stepper.advance_frame();
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        seconds.push_back(elapsed);
        total += elapsed;
        outcome.frames_run = f + 1;
        if (!sound || !stepper.is_finite()) {
            outcome.diverged = true;
            break;
        }
        if (f + 1 < frames && (total > max_run_seconds || stop_requested)) {
            outcome.cut_short = true;
            break;
        }
    }
    if (seconds.size() > 1) seconds.erase(seconds.begin());
    std::sort(seconds.begin(), seconds.end());
    outcome.seconds_per_frame = seconds[seconds.size() / 2];
    if (!outcome.diverged && !outcome.cut_short) outcome.positions = stepper.positions();
    return outcome;
}

// RMS over particles of |x - x_ref|, m.
double rms_distance(const std::vector<Vec3>& x, const std::vector<Vec3>& reference) {
    double sum = 0.0;
    for (std::size_t p = 0; p < x.size(); ++p) {
        const Vec3 d = x[p] - reference[p];
        sum += glm::dot(d, d);
    }
    return std::sqrt(sum / static_cast<double>(x.size()));
}

// max over structural springs of |d| / L - 1: how far the cloth is stretched where it is
// stretched most (what "woven cloth stretches a few per cent" is judged on).
double largest_structural_stretch(const Cloth& cloth, const std::vector<Vec3>& x) {
    double largest = 0.0;
    if (const SpringGroup* group = cloth.find_group(SpringFamily::structural))
        for (const Spring& s : group->springs)
            largest = std::max(largest, glm::length(x[s.j] - x[s.i]) / s.rest_length - 1.0);
    return largest;
}

std::string milliseconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g ms", seconds * 1e3);
    return text;
}

// The methods and settings of the study, all from the same initial state. Each stepper
// owns its state through a shared_ptr captured by its lambdas.
std::vector<Stepper> steppers_for(const Simulation& start, double explicit_dt, int explicit_steps) {
    std::vector<Stepper> steppers;
    const auto weft_stepper = [&](const std::string& method, const std::string& setting,
                                  Integrator integrator, int steps_per_frame,
                                  bool single_precision_springs = false) {
        auto run = std::make_shared<Simulation>(start);
        SimulationOptions options = run->options();
        options.single_precision_springs = single_precision_springs;
        run->set_options(options);
        run->set_integrator(integrator);
        run->set_dt(frame / steps_per_frame);
        steppers.push_back({method, setting, frame / steps_per_frame, steps_per_frame,
                            run->thread_count(),
                            [run, steps_per_frame] {
                                for (int s = 0; s < steps_per_frame; ++s)
                                    if (run->step().diverged()) return false;
                                return true;
                            },
                            [] { return true; },  // weft's own divergence guard did it
                            [run] { return run->cloth().positions; }});
    };
    weft_stepper("weft symplectic Euler", "dt " + milliseconds_text(explicit_dt),
                 Integrator::symplectic_euler, explicit_steps);
    weft_stepper("weft symplectic Euler (float springs)", "dt " + milliseconds_text(explicit_dt),
                 Integrator::symplectic_euler, explicit_steps, true);
    for (int steps : {1, 2, 4})
        weft_stepper("weft implicit Euler", "dt 1/" + std::to_string(60 * steps) + " s",
                     Integrator::implicit_euler, steps);
    for (int substeps : {5, 10, 20, 40}) {
        auto xpbd = std::make_shared<XpbdCloth>(start.cloth(), start.force_field());
        steppers.push_back(
            {"XPBD float", std::to_string(substeps) + " substeps", frame / substeps, substeps, 1,
             [xpbd, substeps] {
                 xpbd->step_frame(frame, substeps);
                 return true;
             },
             [xpbd] { return xpbd->is_finite(); }, [xpbd] { return xpbd->positions(); }});
    }
    auto plain = std::make_shared<PlainFloatCloth>(start.cloth(), start.force_field());
    const auto plain_dt = static_cast<float>(explicit_dt);
    steppers.push_back(
        {"plain float step", "dt " + milliseconds_text(explicit_dt), explicit_dt, explicit_steps, 1,
         [plain, plain_dt, explicit_steps] {
             for (int s = 0; s < explicit_steps; ++s) plain->step_symplectic_euler(plain_dt);
             return true;
         },
         [plain] { return plain->is_finite(); }, [plain] { return plain->positions(); }});
    return steppers;
}

// Seconds to draw the cloth shaded at 1280x720 through the scene's camera on the machine's
// threads, as the demo draws a frame.
double drawing_seconds(const Scene& scene, const Cloth& cloth) {
    WorkerPool pool(default_thread_count());
    raster::Framebuffer framebuffer(1280, 720);
    view::ClothView cloth_view(cloth);
    const view::FrameOptions options;
    const float ground = view::ground_height_below(cloth);
    const raster::Camera camera = view::scene_camera(scene);
    return seconds_per_call([&] {
        view::render_frame(framebuffer, camera, cloth, cloth_view, options, ground, {}, &pool);
    });
}

}  // namespace

int run_realtime_study(const RealtimeOptions& options) {
    std::string why;
    const auto base = load_study_scene(options.scene, options.overrides, why);
    if (!base) {
        std::fprintf(stderr, "%s\n", why.c_str());
        return 2;
    }
    std::filesystem::create_directories(options.out_dir);
    const std::string csv_path = options.out_dir + "/realtime.csv";
    CsvFile csv(csv_path,
                {"particles_per_side", "particles", "springs", "method", "setting", "dt_s",
                 "steps_per_frame", "threads", "step_seconds_per_frame", "draw_seconds",
                 "frame_seconds", "fits_60fps", "rms_error_m", "largest_stretch", "outcome"});
    if (!csv.is_open()) {
        std::fprintf(stderr, "error: %s: cannot write\n", csv_path.c_str());
        return 2;
    }
    const int frames = std::max(1, static_cast<int>(std::lround(options.duration / frame)));
    std::printf(
        "weft-bench realtime on %s, %d threads for weft\n"
        "material: %s (%s), resized to each sheet; %d frames of 1/60 s (%.3g s) from the "
        "scene's start;\nerror: RMS distance to weft's symplectic Euler at a quarter of its "
        "step limit at the end; stretch: largest over structural springs at the end\n",
        machine_description().c_str(), default_thread_count(), base->name.c_str(),
        options.scene.c_str(), frames, frames * frame);

    for (int n : options.sizes) {
        if (stop_requested) break;
        const Scene scene = resized_sheet(*base, n);
        const Simulation start(scene);
        const Cloth& cloth = start.cloth();
        // Symplectic Euler at its step-limit estimate, rounded down to a whole number of
        // steps per frame, so every method ends at the same simulated time.
        const double limit =
            estimated_step_limit(cloth, scene.forces.air_drag, Integrator::symplectic_euler);
        const int explicit_steps = static_cast<int>(std::ceil(frame / limit - 1e-9));
        const double explicit_dt = frame / explicit_steps;
        std::printf(
            "\n%dx%d: %zu particles, %zu springs; symplectic Euler step limit %s -> "
            "%d steps a frame\n",
            n, n, cloth.particle_count(), cloth.spring_count(), milliseconds_text(limit).c_str(),
            explicit_steps);

        // The converged reference: a quarter of that step, from the same state.
        Simulation reference = start;
        reference.set_integrator(Integrator::symplectic_euler);
        reference.set_dt(explicit_dt / 4);
        const double reference_seconds = seconds_of(
            [&] { run_steps(reference, static_cast<long long>(frames) * 4 * explicit_steps); });
        if (stop_requested) break;
        if (reference.steps_taken() != static_cast<std::uint64_t>(frames) * 4 * explicit_steps) {
            std::printf("  the reference diverged: nothing to measure against at this size\n");
            continue;
        }
        const std::vector<Vec3>& reference_positions = reference.cloth().positions;
        std::printf("  reference: dt %s, %.1f s of CPU; its stretch %.1f %%\n",
                    milliseconds_text(explicit_dt / 4).c_str(), reference_seconds,
                    100.0 * largest_structural_stretch(cloth, reference_positions));

        const double draw = drawing_seconds(scene, reference.cloth());

        // weft's step against the plain float step, same dt and state, interleaved.
        // (The scene may ask for another integrator: the cloth-like scenes use implicit Euler.)
        // The same with the spring forces in float (SimulationOptions::single_precision_springs).
        Simulation weft_run = start, weft_single = start, float_run = start, float_single = start;
        for (Simulation* run : {&weft_run, &weft_single, &float_run, &float_single}) {
            run->set_integrator(Integrator::symplectic_euler);
            run->set_dt(explicit_dt);
        }
        SimulationOptions float_springs = float_run.options();
        float_springs.single_precision_springs = true;
        for (Simulation* run : {&float_run, &float_single}) run->set_options(float_springs);
        weft_single.set_thread_count(1);
        float_single.set_thread_count(1);
        PlainFloatCloth plain(cloth, start.force_field());
        const Interleaved versus = interleaved_seconds(
            {[&] { plain.step_symplectic_euler(static_cast<float>(explicit_dt)); },
             [&] { weft_run.step(); }, [&] { weft_single.step(); }, [&] { float_run.step(); },
             [&] { float_single.step(); }},
            5, 0.05);
        std::printf(
            "  drawing 1280x720 shaded: %s; weft's symplectic Euler step / the plain float "
            "step: %.2f on %d threads, %.2f on 1; with float springs %.2f and %.2f (%.1f / %.1f "
            "/ %.1f / %.1f / %.1f us)\n",
            milliseconds_text(draw).c_str(), versus.ratio_to_first[1], weft_run.thread_count(),
            versus.ratio_to_first[2], versus.ratio_to_first[3], versus.ratio_to_first[4],
            versus.seconds[1] * 1e6, versus.seconds[2] * 1e6, versus.seconds[3] * 1e6,
            versus.seconds[4] * 1e6, versus.seconds[0] * 1e6);
        const std::string side = std::to_string(n),
                          particles = cell(double(cloth.particle_count())),
                          springs = cell(double(cloth.spring_count()));
        csv.write_row({side, particles, springs, "weft symplectic Euler / plain float step",
                       "dt " + cell(explicit_dt), cell(explicit_dt), "", "",
                       cell(versus.ratio_to_first[1]), "", "", "", "", "",
                       "ratio of step times on " + std::to_string(weft_run.thread_count()) +
                           " threads; on 1 thread " + cell(versus.ratio_to_first[2])});
        csv.write_row({side, particles, springs,
                       "weft symplectic Euler (float springs) / plain float step",
                       "dt " + cell(explicit_dt), cell(explicit_dt), "", "",
                       cell(versus.ratio_to_first[3]), "", "", "", "", "",
                       "ratio of step times on " + std::to_string(float_run.thread_count()) +
                           " threads; on 1 thread " + cell(versus.ratio_to_first[4])});

        std::printf("  %-37s %-14s %7s %9s %9s %5s %13s %8s\n", "method", "setting", "threads",
                    "ms/frame", "+drawing", "60fps", "rms error (m)", "stretch");
        PlotSpec plot{std::to_string(n) + "x" + std::to_string(n) +
                          ": cost of a 1/60 s frame against error (" + machine_description() + ")",
                      "CPU seconds per simulated 1/60 s frame (median)",
                      "RMS error at the end (m)"};
        struct Choice {
            std::string method, cheapest, most_accurate;
            double cheapest_cost = INFINITY, best_error = INFINITY;
        };
        std::vector<Choice> choices;
        double smallest_error = INFINITY, largest_error = 0.0;
        double explicit_error = not_measured;  // weft's symplectic Euler at its step limit
        const std::vector<Stepper> steppers = steppers_for(start, explicit_dt, explicit_steps);
        for (const Stepper& stepper : steppers) {
            if (stop_requested) break;
            const Outcome outcome = run_frames(stepper, frames, options.max_run_seconds);
            const double error = outcome.positions.empty()
                                     ? not_measured
                                     : rms_distance(outcome.positions, reference_positions);
            const double stretch = outcome.positions.empty()
                                       ? not_measured
                                       : largest_structural_stretch(cloth, outcome.positions);
            const double total = outcome.seconds_per_frame + draw;
            const bool fits = !outcome.diverged && total <= frame;
            const std::string result =
                outcome.diverged ? "diverged in frame " + std::to_string(outcome.frames_run)
                : outcome.cut_short
                    ? "cut short after " + std::to_string(outcome.frames_run) + " frames"
                    : "ok";
            std::printf("  %-37s %-14s %7d %9.2f %9.2f %5s %13.3g %7.1f %%%s%s\n",
                        stepper.method.c_str(), stepper.setting.c_str(), stepper.threads,
                        outcome.seconds_per_frame * 1e3, total * 1e3, fits ? "yes" : "no", error,
                        100.0 * stretch, result == "ok" ? "" : "  ",
                        result == "ok" ? "" : result.c_str());
            std::fflush(stdout);  // a long run shows its progress through a pipe too
            csv.write_row({side, particles, springs, stepper.method, stepper.setting,
                           cell(stepper.dt), std::to_string(stepper.steps_per_frame),
                           std::to_string(stepper.threads), cell(outcome.seconds_per_frame),
                           cell(draw), cell(total), fits ? "yes" : "no", cell(error), cell(stretch),
                           result});
            if (plot.series.empty() || plot.series.back().label != stepper.method) {
                plot.series.push_back(
                    {stepper.method, series_colour(static_cast<int>(plot.series.size()))});
                choices.push_back({stepper.method, "", ""});
            }
            plot.series.back().points.push_back({outcome.seconds_per_frame, error});
            if (std::isfinite(error)) {
                smallest_error = std::min(smallest_error, error);
                largest_error = std::max(largest_error, error);
            }
            if (&stepper == &steppers.front()) explicit_error = error;
            Choice& choice = choices.back();
            if (fits && outcome.seconds_per_frame < choice.cheapest_cost) {
                choice.cheapest_cost = outcome.seconds_per_frame;
                choice.cheapest = stepper.setting;
            }
            if (fits && std::isfinite(error) && error < choice.best_error) {
                choice.best_error = error;
                choice.most_accurate = stepper.setting;
            }
        }
        // Symplectic Euler is first order: at a quarter of the step its error is a quarter,
        // so |x(dt) - x(dt/4)| is 3/4 of x(dt)'s error and the reference's own is a third of
        // that. Errors below it are not resolved.
        std::printf("  the reference's own error, estimated (first order): %.3g m\n",
                    explicit_error / 3);
        csv.write_row({side, particles, springs, "reference", "dt " + cell(explicit_dt / 4),
                       cell(explicit_dt / 4), std::to_string(4 * explicit_steps),
                       std::to_string(reference.thread_count()), cell(reference_seconds / frames),
                       "", "", "", cell(explicit_error / 3), "", "own error estimated"});
        std::printf("  at 60 fps with the frame drawn (%s of the 16.7 ms left for stepping):\n",
                    milliseconds_text(frame - draw).c_str());
        for (const Choice& choice : choices) {
            if (choice.cheapest.empty())
                std::printf("    %-37s none fits\n", choice.method.c_str());
            else
                std::printf("    %-37s cheapest that fits: %s; most accurate that fits: %s\n",
                            choice.method.c_str(), choice.cheapest.c_str(),
                            choice.most_accurate.empty() ? "(no error measured)"
                                                         : choice.most_accurate.c_str());
            csv.write_row(
                {side, particles, springs, choice.method, "summary", "", "", "", "", cell(draw), "",
                 choice.cheapest.empty() ? "no" : "yes", "", "",
                 "cheapest that fits: " + (choice.cheapest.empty() ? "none" : choice.cheapest) +
                     "; most accurate that fits: " +
                     (choice.most_accurate.empty() ? "none" : choice.most_accurate)});
        }
        // The budget left after drawing, as a dashed vertical line across the errors, and
        // the reference's own error, as a dashed horizontal one across the costs.
        double cheapest = INFINITY, dearest = 0.0;
        for (const PlotSeries& series : plot.series)
            for (const PlotPoint& point : series.points)
                if (std::isfinite(point.x))
                    cheapest = std::min(cheapest, point.x), dearest = std::max(dearest, point.x);
        if (frame > draw && largest_error > 0.0)
            plot.series.push_back({"60 fps budget",
                                   raster::Rgba8{0, 0, 0, 255},
                                   {{frame - draw, smallest_error}, {frame - draw, largest_error}},
                                   true,
                                   false});
        if (explicit_error > 0.0 && dearest > 0.0)
            plot.series.push_back({"reference's error",
                                   raster::Rgba8{128, 128, 128, 255},
                                   {{cheapest, explicit_error / 3}, {dearest, explicit_error / 3}},
                                   true,
                                   false});
        plot.notes = {"budget: 1/60 s less",
                      "the drawing",
                      "reference: weft",
                      "symplectic Euler",
                      "at dt " + milliseconds_text(explicit_dt / 4),
                      "plain float step:",
                      "symplectic Euler",
                      "at weft's dt",
                      "XPBD, plain: 1 thread"};
        const std::string png = options.out_dir + "/realtime_" + side + ".png";
        if (!write_plot_png(plot, png, &why))
            std::fprintf(stderr, "error: %s: %s\n", png.c_str(), why.c_str());
    }
    std::printf("\nwrote %s and %s/realtime_<side>.png\n", csv_path.c_str(),
                options.out_dir.c_str());
    return stop_requested ? 130 : 0;
}

}  // namespace weft::bench
