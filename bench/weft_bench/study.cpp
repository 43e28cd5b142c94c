#include "study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <functional>
#include <thread>

#include "sim/scene_io/scene_loader.h"

namespace weft::bench {

std::atomic<bool> stop_requested{false};

void install_stop_handler() {
    std::signal(SIGINT, [](int) { stop_requested = true; });
}

std::optional<Scene> load_study_scene(const std::string& path,
                                      const std::vector<std::string>& overrides,
                                      std::string& error) {
    SceneLoadResult loaded = load_scene_file(path, overrides);
    if (!loaded.ok()) {
        error = loaded.error->message();
        return std::nullopt;
    }
    if (auto why = Simulation::unsupported_feature(*loaded.scene)) {
        error = "error: " + path + ": " + *why;
        return std::nullopt;
    }
    return loaded.scene;
}

bool run_steps(Simulation& simulation, long long steps) {
    for (long long s = 0; s < steps; ++s)
        if (simulation.step().diverged()) return false;
    return true;
}

double seconds_of(const std::function<void()>& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median_seconds(int repeats, const std::function<void()>& work) {
    // At least one timing, as min_seconds: a median of nothing has no first element to read.
    std::vector<double> times{seconds_of(work)};
    for (int r = 1; r < repeats; ++r) times.push_back(seconds_of(work));
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

double min_seconds(int repeats, const std::function<void()>& work) {
    double least = seconds_of(work);
    for (int r = 1; r < repeats; ++r) least = std::min(least, seconds_of(work));
    return least;
}

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
            } while (
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() <
                0.2);
        });
        samples.push_back(elapsed / static_cast<double>(calls));
    }
    std::sort(samples.begin(), samples.end());
    return samples[1];
}

Interleaved interleaved_seconds(const std::vector<std::function<void()>>& works, int rounds,
                                double slice_seconds) {
    for (const auto& work : works) work();
    std::vector<std::vector<double>> samples(works.size());
    for (int round = 0; round < rounds; ++round) {
        for (std::size_t k = 0; k < works.size(); ++k) {
            long long calls = 0;
            const auto start = std::chrono::steady_clock::now();
            double elapsed = 0.0;
            do {
                works[k]();
                ++calls;
                elapsed =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            } while (elapsed < slice_seconds);
            samples[k].push_back(elapsed / static_cast<double>(calls));
        }
    }
    auto median = [](std::vector<double> values) {
        std::sort(values.begin(), values.end());
        return values[values.size() / 2];
    };
    Interleaved result;
    for (std::size_t k = 0; k < works.size(); ++k) {
        result.seconds.push_back(median(samples[k]));
        result.fastest.push_back(*std::min_element(samples[k].begin(), samples[k].end()));
        std::vector<double> ratios;
        for (int round = 0; round < rounds; ++round)
            ratios.push_back(samples[k][round] / samples[0][round]);
        result.ratio_to_first.push_back(median(ratios));
    }
    return result;
}

const char* short_name(Integrator integrator) {
    return integrator_name(integrator);
}

std::string machine_description() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, model = "unknown CPU";
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    }
    return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " cores";
}

double fitted_log_slope(const std::vector<double>& xs, const std::vector<double>& ys) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const auto n = static_cast<double>(xs.size());
    for (std::size_t k = 0; k < xs.size(); ++k) {
        const double x = std::log(xs[k]), y = std::log(ys[k]);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double denominator = n * sxx - sx * sx;
    return denominator != 0.0 ? (n * sxy - sx * sy) / denominator : std::nan("");
}

}  // namespace weft::bench
