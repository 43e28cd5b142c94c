// Where a run's steps spend their time, phase by phase, and how its solves went: the times a
// profiled Simulation puts in each StepReport (StepTimes), and their sum over a run
// (StepProfile), which `weft --headless --profile` prints and the panel shows.
#pragma once

#include <chrono>
#include <cstdint>

namespace weft {

// Implicit Euler's share of a step's integrate phase (s, wall clock), over all its pieces.
struct ImplicitPhaseTimes {
    double setup = 0.0;          // forces, per-spring terms, contacts held, first residual
    double coarse_levels = 0.0;  // building the preconditioner's coarse levels
    double iterations = 0.0;     // the conjugate-gradient iterations, coarse cycles included
    double split_checks = 0.0;   // judging each piece's linearisation, and the copies a split
                                 // goes back to
    double total() const { return setup + coarse_levels + iterations + split_checks; }
    // Adds `other` × weight (-1: takes it away).
    void add(const ImplicitPhaseTimes& other, double weight = 1.0) {
        setup += weight * other.setup;
        coarse_levels += weight * other.coarse_levels;
        iterations += weight * other.iterations;
        split_checks += weight * other.split_checks;
    }
};

// Adds the wall time since the last lap to one phase; reads no clock when off.
class PhaseClock {
  public:
    explicit PhaseClock(bool on) : on_(on) {
        if (on_) mark_ = Clock::now();
    }
    void lap(double& phase) {
        if (!on_) return;
        const Clock::time_point now = Clock::now();
        phase += std::chrono::duration<double>(now - mark_).count();
        mark_ = now;
    }

  private:
    using Clock = std::chrono::steady_clock;
    bool on_;
    Clock::time_point mark_{};
};

// One step's phases, in the order Simulation::step takes them (s, wall clock). A step taken
// again after the cloth slipped from the hand counts both tries.
struct StepTimes {
    double integrate = 0.0;  // the integrator's step: forces, and implicit Euler's solve
                             // with its splits (the fused grid step also resolves the
                             // contacts on its rows, counted here then)
    double strain_limit = 0.0;
    double contacts = 0.0;  // impulse contacts, self-collision and the hand's hold
    double tearing = 0.0;
    double guards = 0.0;          // divergence, runaway-tearing and energy guards
    ImplicitPhaseTimes implicit;  // part of integrate, by implicit Euler
    double total() const { return integrate + strain_limit + contacts + tearing + guards; }
    // Adds `other` × weight (-1: takes it away).
    void add(const StepTimes& other, double weight = 1.0) {
        integrate += weight * other.integrate;
        strain_limit += weight * other.strain_limit;
        contacts += weight * other.contacts;
        tearing += weight * other.tearing;
        guards += weight * other.guards;
        implicit.add(other.implicit, weight);
    }
};

struct StepProfile {
    std::uint64_t steps = 0;
    std::uint64_t held_steps = 0;  // with the hand holding the cloth
    std::uint64_t slips = 0;       // steps in which the cloth slipped from the hand
    StepTimes seconds;             // summed over the steps
    std::uint64_t force_evaluations = 0;
    // Implicit Euler: conjugate-gradient iterations, halvings and Newton iterations (a piece
    // linearised again where it ended), over all a step's pieces.
    std::uint64_t solver_iterations = 0;
    int most_iterations = 0;  // in one step
    std::uint64_t splits = 0;
    int most_splits = 0;
    std::uint64_t newton_iterations = 0;
    std::uint64_t tries_stopped_early = 0;  // at the early judgement (implicit_grid_solve.h)

    void add(const StepTimes& times, bool held, bool slipped, std::uint64_t force_evaluations_added,
             int iterations, int step_splits, int step_newton_iterations,
             int step_tries_stopped_early) {
        ++steps;
        held_steps += held ? 1 : 0;
        slips += slipped ? 1 : 0;
        seconds.add(times);
        force_evaluations += force_evaluations_added;
        solver_iterations += static_cast<std::uint64_t>(iterations);
        most_iterations = iterations > most_iterations ? iterations : most_iterations;
        splits += static_cast<std::uint64_t>(step_splits);
        most_splits = step_splits > most_splits ? step_splits : most_splits;
        newton_iterations += static_cast<std::uint64_t>(step_newton_iterations);
        tries_stopped_early += static_cast<std::uint64_t>(step_tries_stopped_early);
    }
    // What was added since `earlier`, a copy of this profile taken before (the largest
    // counts in one step stay this profile's: since the run began).
    StepProfile since(const StepProfile& earlier) const {
        StepProfile part = *this;
        part.steps -= earlier.steps;
        part.held_steps -= earlier.held_steps;
        part.slips -= earlier.slips;
        part.seconds.add(earlier.seconds, -1.0);
        part.force_evaluations -= earlier.force_evaluations;
        part.solver_iterations -= earlier.solver_iterations;
        part.splits -= earlier.splits;
        part.newton_iterations -= earlier.newton_iterations;
        part.tries_stopped_early -= earlier.tries_stopped_early;
        return part;
    }
};

}  // namespace weft
