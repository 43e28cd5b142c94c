// What the studies share: loading their scenes, running a simulation for a stretch of
// simulated time, timing it, and stopping cleanly on Ctrl-C.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sim/core/simulation.h"
#include "sim/scene/scene.h"

namespace weft::bench {

// Set by SIGINT: studies finish the run in progress, write what they have, and return.
extern std::atomic<bool> stop_requested;
void install_stop_handler();

// The scene at `path` with `overrides`, or an error message.
std::optional<Scene> load_study_scene(const std::string& path,
                                      const std::vector<std::string>& overrides,
                                      std::string& error);

// Runs `steps` steps; nothing if the simulation diverged (or was stopped).
bool run_steps(Simulation& simulation, long long steps);

// Wall-clock seconds of a callable, and the median or the least of `repeats` timings (the
// least is the one that other processes on a shared machine disturbed least). Both time the
// work at least once, whatever `repeats` says.
double seconds_of(const std::function<void()>& work);
double median_seconds(int repeats, const std::function<void()>& work);
double min_seconds(int repeats, const std::function<void()>& work);

// Seconds per call of `work`: repeated until at least 0.2 s have passed, the median of
// three such measurements, after one warm-up call.
double seconds_per_call(const std::function<void()>& work);

// Median seconds per call of each of several callables, measured in interleaved rounds (a
// slice of each in turn, `rounds` times) so that load from other processes on the machine
// falls on all of them alike; also the median over rounds of each one's time divided by the
// first's, the ratio least disturbed by that load.
struct Interleaved {
    std::vector<double> seconds;         // median per callable
    std::vector<double> fastest;         // the fastest round's per callable
    std::vector<double> ratio_to_first;  // median over rounds of seconds[k] / seconds[0]
};
Interleaved interleaved_seconds(const std::vector<std::function<void()>>& works, int rounds = 9,
                                double slice_seconds = 0.08);

const char* short_name(Integrator integrator);
inline constexpr Integrator explicit_integrators[] = {
    Integrator::explicit_euler, Integrator::symplectic_euler, Integrator::verlet,
    Integrator::velocity_verlet, Integrator::rk4};
inline constexpr Integrator all_integrators[] = {Integrator::explicit_euler,
                                                 Integrator::symplectic_euler,
                                                 Integrator::verlet,
                                                 Integrator::velocity_verlet,
                                                 Integrator::rk4,
                                                 Integrator::implicit_euler};

// "AMD EPYC, 2 cores": for the header of every report.
std::string machine_description();

// Least-squares slope of log y against log x: the observed order of convergence.
double fitted_log_slope(const std::vector<double>& xs, const std::vector<double>& ys);

}  // namespace weft::bench
