#include "throughput_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <vector>

#include "csv_file.h"
#include "parallel/worker_pool.h"
#include "plain_baseline.h"
#include "plot.h"
#include "raster/framebuffer.h"
#include "sim/build/cloth_builder.h"
#include "sim/grid/grid_force_pass.h"
#include "sim/guards/stability_limit.h"
#include "study.h"
#include "view/frame_renderer.h"

namespace weft::bench {
namespace {

// A sheet of n × n particles of the scene's material: 1.15 m across whatever n is, with the
// scene's areal density, and all three spring families.
Scene sheet_of_size(const Scene& base, int n) {
    Scene scene = base;
    const double spacing = 1.15 / (n - 1);
    scene.cloth.particle_mass =
        base.cloth.particle_mass * (spacing / base.cloth.spacing) * (spacing / base.cloth.spacing);
    scene.cloth.spacing = spacing;
    scene.cloth.rows = scene.cloth.cols = n;
    scene.shear.enabled = scene.bend.enabled = true;
    return scene;
}

// The triad a[i] = b[i] + s c[i] over arrays far larger than the caches: the memory
// bandwidth this machine sustains (bytes moved / second, best of five).
double triad_bandwidth() {
    const std::size_t count = std::size_t{1} << 25;  // 256 MiB per array
    std::vector<double> a(count, 0.0), b(count, 1.0), c(count, 2.0);
    double best = 0.0;
    for (int repeat = 0; repeat < 5; ++repeat) {
        const double seconds = seconds_of([&] {
            for (std::size_t i = 0; i < count; ++i) a[i] = b[i] + 3.0 * c[i];
        });
        best = std::max(best, 3.0 * sizeof(double) * static_cast<double>(count) / seconds);
    }
    if (a[count / 2] != 7.0) std::fprintf(stderr, "triad check failed\n");  // keeps the loop
    return best;
}

// Seconds per frame of one frame drawn on the pool's threads ([0]) and on one ([1]),
// interleaved over `rounds` rounds.
Interleaved frame_seconds(raster::Framebuffer& framebuffer, const raster::Camera& camera,
                          const Cloth& cloth, std::span<const Collider> colliders,
                          view::ClothView& cloth_view, const view::FrameOptions& frame,
                          float ground, WorkerPool& pool, int rounds) {
    return interleaved_seconds({[&] {
                                    view::render_frame(framebuffer, camera, cloth, cloth_view,
                                                       frame, ground, colliders, &pool);
                                },
                                [&] {
                                    view::render_frame(framebuffer, camera, cloth, cloth_view,
                                                       frame, ground, colliders);
                                }},
                               rounds);
}

// The demo's 128² sheet as the demo shows it: large_rubber_sheet.toml stepped 2 s with its own
// integrator and dt (hanging from its pins, across a good part of the screen), drawn shaded
// at 1280x720 through its camera; and whether a demo frame — the steps of 1/60 s and that
// drawing — fits in 1/60 s.
void measure_demo_view(const std::string& path, CsvFile& csv) {
    std::string error;
    const auto scene = load_study_scene(path, {}, error);
    if (!scene) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return;
    }
    Simulation simulation(*scene);
    const double dt = scene->solver.dt;
    if (!run_steps(simulation, static_cast<long long>(std::ceil(2.0 / dt)))) {
        std::printf("\n%s diverged within 2 s: not drawn\n", path.c_str());
        return;
    }
    const Cloth& cloth = simulation.cloth();
    WorkerPool pool(default_thread_count());
    raster::Framebuffer framebuffer(1280, 720);
    view::ClothView cloth_view(cloth);
    const view::FrameOptions frame;
    const float ground = view::ground_height_below(cloth, simulation.colliders());
    const Interleaved seconds =
        frame_seconds(framebuffer, view::scene_camera(*scene), cloth, simulation.colliders(),
                      cloth_view, frame, ground, pool, 9);
    long long covered = 0;
    for (float depth : framebuffer.depths()) covered += depth < 1.0f ? 1 : 0;
    Simulation stepping = simulation;
    const double step_seconds = seconds_per_call([&] { stepping.step(); });
    const double frame_seconds =
        std::ceil((1.0 / 60.0) / dt - 1e-9) * step_seconds + seconds.seconds[0];
    std::printf(
        "\n%s (%zu particles) after 2 s, as the demo shows it (%.0f %% of the pixels):\n"
        "  render 1280x720 shaded                %.2f ms on %d threads, %.2f ms on 1 "
        "(median of 9 rounds; fastest round %.2f and %.2f ms)\n"
        "  demo frame at 60 fps (%s at dt %.3g s, %.0f steps of %.1f us, and the drawing): "
        "%.1f ms -> %s\n",
        path.c_str(), cloth.particle_count(),
        100.0 * static_cast<double>(covered) / (1280.0 * 720.0), seconds.seconds[0] * 1e3,
        pool.thread_count(), seconds.seconds[1] * 1e3, seconds.fastest[0] * 1e3,
        seconds.fastest[1] * 1e3, integrator_name(scene->solver.integrator), dt,
        std::ceil((1.0 / 60.0) / dt - 1e-9), step_seconds * 1e6, frame_seconds * 1e3,
        frame_seconds <= 1.0 / 60.0 ? "real time" : "slower than real time");
    const std::string particles = cell(static_cast<double>(cloth.particle_count()));
    csv.write_row({"demo", particles, "", "render 1280x720 shaded, demo view", "",
                   cell(seconds.seconds[0]), "", "",
                   "1 thread " + cell(seconds.seconds[1]) + "; fastest rounds " +
                       cell(seconds.fastest[0]) + " and " + cell(seconds.fastest[1])});
    csv.write_row({"demo", particles, "", "demo_frame_at_60fps",
                   integrator_name(scene->solver.integrator), cell(frame_seconds), "", "",
                   "step " + cell(step_seconds) + " s at dt " + cell(dt)});
}

}  // namespace

int run_throughput_study(const ThroughputOptions& options) {
    std::string error;
    auto base = load_study_scene(options.scene, options.overrides, error);
    if (!base) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return 2;
    }
    std::filesystem::create_directories(options.out_dir);
    const std::string csv_path = options.out_dir + "/throughput.csv";
    CsvFile csv(csv_path, {"particles_per_side", "particles", "springs", "what", "integrator",
                           "seconds", "springs_per_second", "particle_steps_per_second", "note"});
    if (!csv.is_open()) {
        std::fprintf(stderr, "error: %s: cannot write\n", csv_path.c_str());
        return 2;
    }
    std::printf("weft-bench throughput on %s\n", machine_description().c_str());
    const double bandwidth = triad_bandwidth();
    std::printf("memory bandwidth (triad): %.2f GB/s\n", bandwidth / 1e9);
    csv.write_row(
        {"", "", "", "triad_bandwidth_bytes_per_second", "", cell(bandwidth), "", "", ""});

    PlotSpec plot{"Time per step, all spring families (" + machine_description() + ")", "particles",
                  "seconds per step (median)"};
    std::vector<PlotSeries> series;
    for (Integrator integrator : all_integrators)
        series.push_back(
            {integrator_name(integrator), series_colour(static_cast<int>(series.size()))});
    series.push_back({"plain baseline (symplectic euler)", raster::Rgba8{0, 0, 0, 255}, {}, true});

    std::printf("threads: %d (WEFT_THREADS or the machine's), force kernel: %s\n",
                default_thread_count(), simd_level_name(supported_simd_level()));
    int largest_real_time_at_1ms = 0, largest_real_time_sound = 0;
    for (int n : options.sizes) {
        if (stop_requested) break;
        const Scene scene = sheet_of_size(*base, n);
        // Steps are timed on a sound state: at 90 % of the step limit that counts the dampers
        // (stability_limit.h). At the scene's own dt a large sheet of this material diverges
        // within a few steps, and a diverged state is not worth timing.
        Simulation simulation(scene);
        const double sound_dt = std::min(
            scene.solver.dt, 0.9 * estimated_step_limit(simulation.cloth(), scene.forces.air_drag,
                                                        Integrator::symplectic_euler));
        simulation.set_dt(sound_dt);
        const Cloth& cloth = simulation.cloth();
        const auto particles = static_cast<double>(cloth.particle_count());
        const auto springs = static_cast<double>(cloth.spring_count());
        std::printf("\n%dx%d: %.0f particles, %.0f springs; steps timed at dt %.3g s\n", n, n,
                    particles, springs, sound_dt);

        // The force pass alone, on one thread and on the machine's threads.
        std::vector<Vec3> forces(cloth.particle_count());
        WorkerPool pool(default_thread_count());
        const Interleaved force = interleaved_seconds(
            {[&] {
                 accumulate_forces(cloth, simulation.force_field(), cloth.positions,
                                   cloth.velocities, forces);
             },
             [&] {
                 accumulate_forces(cloth, simulation.force_field(), cloth.positions,
                                   cloth.velocities, forces, &pool);
             }});
        const double single_thread_seconds = force.seconds[0], force_seconds = force.seconds[1];
        std::printf("  force pass, 1 thread %10.1f us\n", single_thread_seconds * 1e6);
        csv.write_row({std::to_string(n), cell(particles), cell(springs), "force_pass_1_thread", "",
                       cell(single_thread_seconds), cell(springs / single_thread_seconds), "", ""});
        // Bytes it must move at least: x, v, f of every particle, and per spring its rest
        // length (the structured pass; the general pass reads a 16-byte record).
        const double force_bytes = springs * 8.0 + particles * 3 * sizeof(Vec3);
        std::printf(
            "  force pass, %d threads %8.1f us  %.3g springs/s  %.1f %% of triad bandwidth\n",
            pool.thread_count(), force_seconds * 1e6, springs / force_seconds,
            100.0 * force_bytes / force_seconds / bandwidth);
        csv.write_row({std::to_string(n), cell(particles), cell(springs), "force_pass", "",
                       cell(force_seconds), cell(springs / force_seconds), "",
                       cell(force_bytes / force_seconds / bandwidth) + " of triad"});

        for (std::size_t k = 0; k < std::size(all_integrators); ++k) {
            const Integrator integrator = all_integrators[k];
            Simulation run = simulation;
            run.set_integrator(integrator);
            long long diverged_steps = 0;
            const double step_seconds =
                seconds_per_call([&] { diverged_steps += run.step().diverged(); });
            std::printf("  %-17s %10.1f us/step  %.3g particle-steps/s%s\n",
                        integrator_name(integrator), step_seconds * 1e6, particles / step_seconds,
                        diverged_steps ? "  (diverged!)" : "");
            csv.write_row({std::to_string(n), cell(particles), cell(springs), "step",
                           integrator_name(integrator), cell(step_seconds), "",
                           cell(particles / step_seconds), diverged_steps ? "diverged" : ""});
            series[k].points.push_back({particles, step_seconds});
        }

        // Symplectic Euler against the plain baseline, both at the same dt from the same
        // state, interleaved: weft on the machine's threads, weft on one, the baseline.
        PlainCloth plain(cloth, simulation.force_field());
        Simulation weft_run = simulation, weft_single = simulation;
        weft_run.set_integrator(Integrator::symplectic_euler);
        weft_single.set_integrator(Integrator::symplectic_euler);
        weft_single.set_thread_count(1);
        // And two ablations of weft's step, so the gain of each is measured: the force pass
        // and the step run separately (no fusion), and the AVX2 build of the kernel where
        // the CPU would take AVX-512.
        Simulation weft_separate = weft_run, weft_avx2 = weft_run;
        const SimdLevel best_level = supported_simd_level();
        SimulationOptions separate = weft_run.options(), avx2 = weft_run.options();
        separate.fused_grid_steps = false;
        avx2.kernel_build = std::min(best_level, SimdLevel::avx2);
        weft_separate.set_options(separate);
        weft_avx2.set_options(avx2);
        const Interleaved versus =
            interleaved_seconds({[&] { weft_run.step(); }, [&] { weft_single.step(); },
                                 [&] { plain.step_symplectic_euler(sound_dt); },
                                 [&] { weft_separate.step(); }, [&] { weft_avx2.step(); }});
        const double weft_seconds = versus.seconds[0], weft_single_seconds = versus.seconds[1];
        const double plain_seconds = versus.seconds[2];
        const double speed_up = versus.ratio_to_first[2];
        const double speed_up_single = versus.ratio_to_first[2] / versus.ratio_to_first[1];
        std::printf(
            "  plain baseline    %10.1f us/step  weft symplectic euler: %.1f us on %d threads "
            "(%.2fx faster), "
            "%.1f us on 1 thread (%.2fx)\n",
            plain_seconds * 1e6, weft_seconds * 1e6, weft_run.thread_count(), speed_up,
            weft_single_seconds * 1e6, speed_up_single);
        std::printf(
            "  weft's step without the fused pass: %.1f us (%.2fx the fused); with the %s "
            "kernel: %.1f us (%.2fx)\n",
            versus.seconds[3] * 1e6, versus.ratio_to_first[3],
            simd_level_name(std::min(best_level, SimdLevel::avx2)), versus.seconds[4] * 1e6,
            versus.ratio_to_first[4]);
        csv.write_row({std::to_string(n), cell(particles), cell(springs), "step_separate_pass",
                       "symplectic-euler", cell(versus.seconds[3]), "", "",
                       "ratio to fused " + cell(versus.ratio_to_first[3])});
        csv.write_row({std::to_string(n), cell(particles), cell(springs), "step_avx2_kernel",
                       "symplectic-euler", cell(versus.seconds[4]), "", "",
                       "ratio to best kernel " + cell(versus.ratio_to_first[4])});
        csv.write_row({std::to_string(n), cell(particles), cell(springs), "step", "plain-baseline",
                       cell(plain_seconds), "", cell(particles / plain_seconds),
                       "weft symplectic-euler speed-up " + cell(speed_up)});
        csv.write_row({std::to_string(n), cell(particles), cell(springs),
                       "step_threads_" + std::to_string(weft_run.thread_count()),
                       "symplectic-euler", cell(weft_seconds), "", cell(particles / weft_seconds),
                       "speed-up over plain baseline " + cell(speed_up)});
        csv.write_row({std::to_string(n), cell(particles), cell(springs), "step_threads_1",
                       "symplectic-euler", cell(weft_single_seconds), "",
                       cell(particles / weft_single_seconds),
                       "speed-up over plain baseline " + cell(speed_up_single)});
        series.back().points.push_back({particles, plain_seconds});

        // Self-collision: the same step with a [self_collision] pass of half a spacing's
        // thickness, against the same sheet without it.
        {
            Scene colliding = scene;
            colliding.self_collision_thickness = 0.5 * scene.cloth.spacing;
            Simulation with(colliding);
            with.set_dt(sound_dt);
            Simulation without = simulation;
            const Interleaved cost =
                interleaved_seconds({[&] { without.step(); }, [&] { with.step(); }}, 5);
            std::printf(
                "  self-collision    %10.1f us/step more (%.1f us with, %.1f without: %.2fx)\n",
                (cost.seconds[1] - cost.seconds[0]) * 1e6, cost.seconds[1] * 1e6,
                cost.seconds[0] * 1e6, cost.ratio_to_first[1]);
            csv.write_row(
                {std::to_string(n), cell(particles), cell(springs), "step_self_collision",
                 "symplectic-euler", cell(cost.seconds[1]), "", cell(particles / cost.seconds[1]),
                 "without " + cell(cost.seconds[0]) + " s, ratio " + cell(cost.ratio_to_first[1])});
        }

        // Drawing: the sheet after it has fallen a little, so it is not a flat square.
        Simulation shaped = simulation;
        run_steps(shaped, static_cast<long long>(std::ceil(0.3 / sound_dt)));
        double render_720p = 0.0;
        for (auto [width, height] : {std::pair{640, 480}, std::pair{1280, 720}}) {
            raster::Framebuffer framebuffer(width, height);
            const double clear_seconds =
                seconds_per_call([&] { framebuffer.clear(raster::Rgba8{}); });
            view::ClothView cloth_view(shaped.cloth());
            for (bool wireframe : {false, true}) {
                view::FrameOptions frame;
                frame.wireframe = wireframe;
                // On the machine's threads (bands) and on one, interleaved.
                const Interleaved seconds =
                    frame_seconds(framebuffer, view::scene_camera(scene), shaped.cloth(), {},
                                  cloth_view, frame, -1.0f, pool, 5);
                if (width == 1280 && !wireframe) render_720p = seconds.seconds[0];
                const std::string what = std::to_string(width) + "x" + std::to_string(height) +
                                         (wireframe ? " shaded+wireframe" : " shaded");
                std::printf(
                    "  render %-27s %7.2f ms on %d threads, %.2f ms on 1 (clearing alone %.2f "
                    "ms)\n",
                    what.c_str(), seconds.seconds[0] * 1e3, pool.thread_count(),
                    seconds.seconds[1] * 1e3, clear_seconds * 1e3);
                csv.write_row(
                    {std::to_string(n), cell(particles), cell(springs), "render " + what, "",
                     cell(seconds.seconds[0]), "", "",
                     "clear " + cell(clear_seconds) + "; 1 thread " + cell(seconds.seconds[1])});
            }
        }
        // Real time at 60 frames per second: the steps of 1/60 s plus one 1280x720 frame
        // within 1/60 s; at dt = 1 ms (17 steps a frame), and at the sound dt above.
        for (double dt : {1e-3, sound_dt}) {
            const double frame_seconds =
                std::ceil((1.0 / 60.0) / dt - 1e-9) * weft_seconds + render_720p;
            const bool real_time = frame_seconds <= 1.0 / 60.0;
            std::printf(
                "  real time at 60 fps (symplectic euler at dt %.3g s, 1280x720): %.1f ms per "
                "frame -> %s\n",
                dt, frame_seconds * 1e3, real_time ? "yes" : "no");
            csv.write_row(
                {std::to_string(n), cell(particles), cell(springs), "frame_at_60fps",
                 "symplectic-euler", cell(frame_seconds), "", "",
                 (real_time ? "real time at dt " : "slower than real time at dt ") + cell(dt)});
            if (real_time && dt == 1e-3) largest_real_time_at_1ms = n;
            if (real_time && dt != 1e-3) largest_real_time_sound = n;
        }
    }
    std::printf(
        "\nlargest sheet in real time with a 1280x720 frame at 60 fps: %dx%d at dt 1 ms; %dx%d at "
        "its sound dt\n",
        largest_real_time_at_1ms, largest_real_time_at_1ms, largest_real_time_sound,
        largest_real_time_sound);
    if (!options.demo_scene.empty() && !stop_requested) measure_demo_view(options.demo_scene, csv);
    plot.series = series;
    const std::string path = options.out_dir + "/throughput.png";
    if (!write_plot_png(plot, path, &error))
        std::fprintf(stderr, "error: %s: %s\n", path.c_str(), error.c_str());
    std::printf("\nwrote %s and %s\n", csv_path.c_str(), path.c_str());
    return stop_requested ? 130 : 0;
}

}  // namespace weft::bench
