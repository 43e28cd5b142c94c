// The demo's frame, drawn as the window draws it: render_frame at 1280x720 through the
// scene's camera, on the shipped cotton-like sheets after half a second of falling (the
// sheet spread over the floor's view, its shadow under it). Each case draws the same cloth
// over and over; the arguments are the sheet's particles per side, shadows off or on, and
// threads. shadow_share draws each frame both ways in turn and reports what shadows add.
//
//   build/release/bench/frame/weft_frame_bench --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true      (on one line)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include "parallel/worker_pool.h"
#include "raster/framebuffer.h"
#include "sim/core/simulation.h"
#include "sim/scene_io/scene_loader.h"
#include "view/cloth_view.h"
#include "view/frame_renderer.h"

namespace {

using namespace weft;

constexpr double settle_seconds = 0.5;  // s of simulated fall before the frame is drawn

// The shipped sheet of this size, stepped for settle_seconds; built once per size.
const Simulation& settled_sheet(int particles_per_side) {
    static std::map<int, std::unique_ptr<Simulation>> sheets;
    auto found = sheets.find(particles_per_side);
    if (found != sheets.end()) return *found->second;
    const std::string path = std::string(WEFT_SOURCE_DIR "/assets/scenes/cloth_") +
                             std::to_string(particles_per_side) + ".toml";
    SceneLoadResult loaded = load_scene_file(path);
    if (!loaded.ok()) {
        std::fprintf(stderr, "%s\n", loaded.error->message().c_str());
        std::exit(2);
    }
    auto simulation = std::make_unique<Simulation>(*loaded.scene);
    const auto steps = static_cast<int>(settle_seconds / loaded.scene->solver.dt + 0.5);
    for (int step = 0; step < steps; ++step) simulation->step();
    return *sheets.emplace(particles_per_side, std::move(simulation)).first->second;
}

// The settled sheet of this size drawn through its scene's camera at 1280x720 on `threads`.
struct FrameDrawer {
    FrameDrawer(int particles_per_side, int threads)
        : simulation(settled_sheet(particles_per_side)),
          camera(view::scene_camera(simulation.scene())),
          pool(threads),
          cloth_view(simulation.cloth()),
          ground(view::ground_height_below(simulation.cloth(), simulation.colliders())) {
        // One frame first, as the window has drawn before any frame it shows: the frames
        // timed reuse what the first one allocated.
        view::render_frame(framebuffer, camera, simulation.cloth(), cloth_view, {}, ground,
                           simulation.colliders(), &pool);
    }

    // Not inlined, so that an instruction count can take exactly the frames timed
    // (valgrind --tool=callgrind --toggle-collect='*FrameDrawer::draw*').
    [[gnu::noinline]] void draw(const view::FrameOptions& options) {
        view::render_frame(framebuffer, camera, simulation.cloth(), cloth_view, options, ground,
                           simulation.colliders(), &pool);
        benchmark::DoNotOptimize(framebuffer.colours().data());
    }

    const Simulation& simulation;
    raster::Camera camera;
    WorkerPool pool;
    raster::Framebuffer framebuffer{1280, 720};
    view::ClothView cloth_view;
    float ground;
};

void draw_frame(benchmark::State& state) {
    const auto particles_per_side = static_cast<int>(state.range(0));
    const bool shadows = state.range(1) != 0;
    const auto threads = static_cast<int>(state.range(2));
    FrameDrawer drawer(particles_per_side, threads);
    view::FrameOptions options;
    options.shadows = shadows;
    for (auto _ : state) drawer.draw(options);
    state.SetLabel(std::to_string(particles_per_side) + "² sheet, shadows " +
                   (shadows ? "on" : "off") + ", " + std::to_string(threads) + " thread(s)");
}

// What the shadows add to a frame, frame by frame: each iteration draws the frame without
// shadows and then with them, so the machine's drift (large on a shared host) falls on both
// alike. Counters: the mean of each, ms, and the shadows' share of the frame without them.
void shadow_share(benchmark::State& state) {
    FrameDrawer drawer(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
    view::FrameOptions without, with;
    without.shadows = false;
    using Clock = std::chrono::steady_clock;
    double seconds_without = 0.0, seconds_with = 0.0;
    for (auto _ : state) {
        for (const bool shadows : {false, true}) {
            const Clock::time_point start = Clock::now();
            drawer.draw(shadows ? with : without);
            (shadows ? seconds_with : seconds_without) +=
                std::chrono::duration<double>(Clock::now() - start).count();
        }
    }
    const auto frames = static_cast<double>(state.iterations());
    state.counters["ms_without"] = 1e3 * seconds_without / frames;
    state.counters["ms_with"] = 1e3 * seconds_with / frames;
    state.counters["shadow_share"] = seconds_with / seconds_without - 1.0;
}

BENCHMARK(shadow_share)
    ->ArgNames({"side", "threads"})
    ->ArgsProduct({{128, 256}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK(draw_frame)
    ->ArgNames({"side", "shadows", "threads"})
    ->ArgsProduct({{128, 256}, {0, 1}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->ComputeStatistics("min",
                        [](const std::vector<double>& v) {
                            return *std::min_element(v.begin(), v.end());
                        })
    ->ComputeStatistics("max", [](const std::vector<double>& v) {
        return *std::max_element(v.begin(), v.end());
    });

}  // namespace

BENCHMARK_MAIN();
