#include "throughput_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <vector>

#include "csv_file.h"
#include "plain_baseline.h"
#include "plot.h"
#include "raster/framebuffer.h"
#include "sim/cloth_builder.h"
#include "sim/stability_limit.h"
#include "sim/worker_pool.h"
#include "study.h"
#include "view/frame_renderer.h"

namespace weft::bench {
namespace {

// Seconds per call of `work`: repeated until at least 0.2 s have passed, the median of
// three such measurements, after one warm-up call.
double seconds_per_call(const std::function<void()>& work) {
    work();
    std::vector<double> samples;
    for (int sample = 0; sample < 3; ++sample) {
        long long calls = 0;
        const double elapsed = seconds_of([&] {
            const auto start = std::chrono::steady_clock::now();
            do {
                work();
                ++calls;
            } while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 0.2);
        });
        samples.push_back(elapsed / static_cast<double>(calls));
    }
    std::sort(samples.begin(), samples.end());
    return samples[1];
}

// A sheet of n × n particles of the scene's material: 1.15 m across whatever n is, with the
// scene's areal density, and all three spring families.
Scene sheet_of_size(const Scene& base, int n) {
    Scene scene = base;
    const double spacing = 1.15 / (n - 1);
    scene.cloth.particle_mass = base.cloth.particle_mass * (spacing / base.cloth.spacing) * (spacing / base.cloth.spacing);
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
    csv.write_row({"", "", "", "triad_bandwidth_bytes_per_second", "", cell(bandwidth), "", "", ""});

    PlotSpec plot{"Time per step, all spring families (" + machine_description() + ")", "particles",
                  "seconds per step (median)"};
    std::vector<PlotSeries> series;
    for (Integrator integrator : all_integrators) series.push_back({integrator_name(integrator), series_colour(static_cast<int>(series.size()))});
    series.push_back({"plain baseline (symplectic euler)", raster::Rgba8{0, 0, 0, 255}, {}, true});

    for (int n : options.sizes) {
        if (stop_requested) break;
        const Scene scene = sheet_of_size(*base, n);
        Simulation simulation(scene);
        const Cloth& cloth = simulation.cloth();
        const auto particles = static_cast<double>(cloth.particle_count());
        const auto springs = static_cast<double>(cloth.spring_count());
        std::printf("\n%dx%d: %.0f particles, %.0f springs\n", n, n, particles, springs);

        // The force pass alone, on one thread and on the machine's threads.
        std::vector<Vec3> forces(cloth.particle_count());
        const double single_thread_seconds = seconds_per_call([&] {
            accumulate_forces(cloth, simulation.force_field(), cloth.positions, cloth.velocities, forces);
        });
        WorkerPool pool(default_thread_count());
        const double force_seconds = seconds_per_call([&] {
            accumulate_forces(cloth, simulation.force_field(), cloth.positions, cloth.velocities, forces, &pool);
        });
        std::printf("  force pass, 1 thread %10.1f us\n", single_thread_seconds * 1e6);
        csv.write_row({std::to_string(n), cell(particles), cell(springs), "force_pass_1_thread", "",
                       cell(single_thread_seconds), cell(springs / single_thread_seconds), "", ""});
        // Bytes it must move at least: each spring record, and x, v, f of every particle.
        const double force_bytes = springs * sizeof(Spring) + particles * 3 * sizeof(Vec3);
        std::printf("  force pass, %d threads %8.1f us  %.3g springs/s  %.1f %% of triad bandwidth\n",
                    pool.thread_count(), force_seconds * 1e6, springs / force_seconds,
                    100.0 * force_bytes / force_seconds / bandwidth);
        csv.write_row({std::to_string(n), cell(particles), cell(springs), "force_pass", "", cell(force_seconds),
                       cell(springs / force_seconds), "", cell(force_bytes / force_seconds / bandwidth) + " of triad"});

        for (std::size_t k = 0; k < std::size(all_integrators); ++k) {
            const Integrator integrator = all_integrators[k];
            Simulation run = simulation;
            run.set_integrator(integrator);
            const double step_seconds = seconds_per_call([&] { run.step(); });
            std::printf("  %-17s %10.1f us/step  %.3g particle-steps/s\n", integrator_name(integrator),
                        step_seconds * 1e6, particles / step_seconds);
            csv.write_row({std::to_string(n), cell(particles), cell(springs), "step", integrator_name(integrator),
                           cell(step_seconds), "", cell(particles / step_seconds), ""});
            series[k].points.push_back({particles, step_seconds});
        }
        PlainCloth plain(cloth, simulation.force_field());
        const double plain_seconds = seconds_per_call([&] { plain.step_symplectic_euler(scene.solver.dt); });
        Simulation weft_run = simulation;
        weft_run.set_integrator(Integrator::symplectic_euler);
        const double weft_seconds = seconds_per_call([&] { weft_run.step(); });
        std::printf("  plain baseline    %10.1f us/step  weft symplectic euler is %.2fx faster\n",
                    plain_seconds * 1e6, plain_seconds / weft_seconds);
        csv.write_row({std::to_string(n), cell(particles), cell(springs), "step", "plain-baseline",
                       cell(plain_seconds), "", cell(particles / plain_seconds),
                       "weft symplectic-euler speed-up " + cell(plain_seconds / weft_seconds)});
        series.back().points.push_back({particles, plain_seconds});

        // Drawing: the sheet after it has fallen a little, so it is not a flat square.
        Simulation shaped = simulation;
        run_steps(shaped, 300);
        double render_720p = 0.0;
        for (auto [width, height] : {std::pair{640, 480}, std::pair{1280, 720}}) {
            raster::Framebuffer framebuffer(width, height);
            const double clear_seconds = seconds_per_call([&] { framebuffer.clear(raster::Rgba8{}); });
            view::ClothView cloth_view(shaped.cloth());
            for (bool wireframe : {false, true}) {
                view::FrameOptions frame;
                frame.wireframe = wireframe;
                const double seconds = seconds_per_call([&] {
                    view::render_frame(framebuffer, view::scene_camera(scene), shaped.cloth(), cloth_view, frame, -1.0f);
                });
                if (width == 1280 && !wireframe) render_720p = seconds;
                const std::string what = std::to_string(width) + "x" + std::to_string(height) + (wireframe ? " shaded+wireframe" : " shaded");
                std::printf("  render %-27s %7.2f ms (clearing alone %.2f ms)\n", what.c_str(), seconds * 1e3, clear_seconds * 1e3);
                csv.write_row({std::to_string(n), cell(particles), cell(springs), "render " + what, "", cell(seconds), "", "",
                               "clear " + cell(clear_seconds)});
            }
        }
        // Real time at 60 frames per second: the steps of 1/60 s at 90 % of the stable step,
        // plus one 1280x720 frame, within 1/60 s.
        const double omega = highest_angular_frequency(cloth, 3000, 1e-6);
        const double dt = 0.9 * stable_step_limit(Integrator::symplectic_euler, omega);
        const double frame_seconds = std::ceil((1.0 / 60.0) / dt) * weft_seconds + render_720p;
        std::printf("  real time at 60 fps (symplectic euler at dt %.3g s, 1280x720): %.1f ms per frame -> %s\n", dt,
                    frame_seconds * 1e3, frame_seconds <= 1.0 / 60.0 ? "yes" : "no");
        csv.write_row({std::to_string(n), cell(particles), cell(springs), "frame_at_60fps", "symplectic-euler",
                       cell(frame_seconds), "", "", frame_seconds <= 1.0 / 60.0 ? "real time" : "slower than real time"});
    }
    plot.series = series;
    const std::string path = options.out_dir + "/throughput.png";
    if (!write_plot_png(plot, path, &error)) std::fprintf(stderr, "error: %s: %s\n", path.c_str(), error.c_str());
    std::printf("\nwrote %s and %s\n", csv_path.c_str(), path.c_str());
    return stop_requested ? 130 : 0;
}

}  // namespace weft::bench
