// Simulation: a cloth, the forces on it and the integrator that steps it, built from a
// Scene. The one object the headless runner, the demo, the benchmarks and the tests drive.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "sim/build/topology_edits.h"
#include "sim/collision/colliders.h"
#include "sim/collision/self_collision.h"
#include "sim/core/cloth.h"
#include "sim/core/force_pass.h"
#include "sim/core/simulation_options.h"
#include "sim/core/step_profile.h"
#include "sim/guards/divergence.h"
#include "sim/guards/energy_guard.h"
#include "sim/guards/runaway_tearing.h"
#include "sim/integrators/integrator.h"
#include "sim/interaction/grab.h"
#include "sim/scene/scene.h"

namespace weft {

struct StepReport {
    std::size_t springs_torn = 0;           // springs that broke in this step
    std::size_t contacts = 0;               // impulse contacts and self-collision pairs resolved
    std::optional<std::string> divergence;  // why the state is no longer sound, if it is not
    bool hand_slipped = false;              // the cloth pulled out of the hand (grab.h)
    bool held = false;                      // the hand held the cloth through the step
    StepTimes times;                        // where the step went, when profiling (s)
    bool diverged() const { return divergence.has_value(); }
};

class Simulation {
  public:
    // The scene must be validated (the loader does that). Throws std::invalid_argument for a
    // valid scene that asks for something not modelled yet (see unsupported_feature).
    explicit Simulation(const Scene& scene, const SimulationOptions& options = {});

    // Why a valid scene cannot be simulated by this build, or nothing.
    static std::optional<std::string> unsupported_feature(const Scene& scene);

    // Advances by one step of dt, then applies what the scene asks for, in this order:
    // strain limiting, impulse contacts with colliders, self-collision, tearing; then the
    // guards look at the new state: the divergence guard, the runaway-tearing guard, the
    // energy guard, and the first to object says why in the report. (Repulsion contacts are
    // forces, inside the step.)
    StepReport step();

    double time() const { return time_; }  // s, simulated
    std::uint64_t steps_taken() const { return steps_taken_; }
    std::uint64_t force_evaluations() const { return workspace_.statistics.force_evaluations; }
    // How implicit Euler's last conjugate-gradient solve went.
    struct LinearSolve {
        int iterations;
        double relative_residual;  // |A Δv - b| / |b|
    };
    LinearSolve last_linear_solve() const {
        return {workspace_.statistics.implicit_iterations,
                workspace_.statistics.implicit_relative_residual};
    }

    // Times the last implicit Euler step was halved (implicit_euler.cpp).
    int last_step_splits() const { return workspace_.statistics.implicit_splits; }
    int last_step_newton_iterations() const {
        return workspace_.statistics.implicit_newton_iterations;
    }
    int last_step_tries_stopped_early() const {
        return workspace_.statistics.implicit_tries_stopped_early;
    }

    // How the steps compute (simulation_options.h); a kernel build the CPU lacks becomes the
    // best it has.
    const SimulationOptions& options() const { return workspace_.settings.options; }
    void set_options(const SimulationOptions& options);

    // When implicit Euler's solve stops (implicit_grid_solve.h).
    void set_implicit_solve_settings(const ImplicitSolveSettings& settings) {
        workspace_.settings.implicit = settings;
    }
    const ImplicitSolveSettings& implicit_solve_settings() const {
        return workspace_.settings.implicit;
    }

    const Cloth& cloth() const { return cloth_; }
    const ForceField& force_field() const { return field_; }
    const Scene& scene() const { return scene_; }
    Integrator integrator() const { return integrator_; }
    double dt() const { return dt_; }

    // Threads for the force pass (default: WEFT_THREADS or the machine's). Results are the
    // same bit for bit whatever the count.
    void set_thread_count(int threads);
    // Whether each step measures its phases into StepReport::times (off: no clock is read).
    void set_profiling(bool on) { workspace_.settings.profiling = on; }
    bool profiling() const { return workspace_.settings.profiling; }
    int thread_count() const { return pool_->thread_count(); }
    // The threads it steps with, for measures taken between steps (energy, stretch).
    WorkerPool* pool() const { return pool_.get(); }

    void set_integrator(Integrator integrator);
    void set_dt(double dt);
    // Live changes of the model (the demo's panel). The scene() kept here follows them, so a
    // reset() restarts with the changed parameters.
    void set_spring_material(SpringFamily family, double stiffness, double damping);
    void set_force_field(const Vec3d& gravity, double air_drag, const Vec3d& wind);
    void set_particle_mass(double mass);
    // Shear and bend springs on or off (structural springs are always on). Off takes the
    // family out of the force pass; on brings it back as it was, or, for a family the scene
    // did not have, builds it where the cloth is still whole (topology_edits.h).
    void set_family_enabled(SpringFamily family,
                            bool enabled);  // kg, every particle; pins stay pinned
    void set_tear_limit(std::optional<double> max_stretch);
    void set_strain_limit(std::optional<double> max_strain);
    // The scene's colliders in its order, then the floor if it has one (floor.h).
    const std::vector<Collider>& colliders() const { return colliders_; }

    // Whether `wanted` differs from the running scene only in what can change while the cloth
    // runs: everything but the cloth's grid, layout, placement and pins and the number and
    // shapes of the colliders (changing those means building a new Simulation).
    static bool live_changeable(const Scene& running, const Scene& wanted);
    // Applies every live parameter of `wanted` (solver, spring families and materials, mass,
    // forces, tearing, strain limit, self-collision, colliders' placement and response,
    // camera, name) through the setters above; a value equal to the running one is left
    // alone, so applying the running scene changes nothing, bit for bit. Requires
    // live_changeable(scene(), wanted).
    void set_parameters(const Scene& wanted);

    // Back to the scene's initial state (with the parameters as they are now).
    void reset();

    // The user's hand: grab the cloth where a ray hits it, pull, let go (grab.h). The hand
    // lets go by itself when the cloth slips from it (StepReport::hand_slipped).
    void start_grab(Grab grab);
    void pull_to(const Vec3& target);
    void let_go();
    const Grab& grab() const { return grab_; }

    // Pins and the cut tool.
    void set_pinned(std::size_t particle, bool pinned);
    void release_all_pins();
    // Removes the springs for which should_cut(spring) is true, with their triangles.
    template <class Predicate>
    std::size_t cut_springs(Predicate should_cut) {
        workspace_.history.valid = false;
        return remove_springs_if(cloth_, should_cut);
    }

    // Edits of the state from outside go through here, so that methods that carry history
    // (the Verlets) restart from the edited state.
    Cloth& edit_cloth();

  private:
    // colliders_ and has_repulsion_ from scene_.colliders, and the floor at floor_height_
    void build_colliders();
    // One step with the hand's motion as prescribed; with `judge_grip`, stops right after the
    // integrator and its corrections, reporting hand_slipped, if the grip slipped.
    StepReport take_step(bool judge_grip);
    // Its phases, in order (simulation.cpp).
    struct StepInProgress;
    void begin_step(StepInProgress& step, StepReport& report);  // the hand, wind, the guard's ask
    void clear_step_field();  // the field lets go of the step's hand and colliders
    void limit_strain_after_step(StepInProgress& step);
    std::size_t resolve_contacts(StepInProgress& step);  // with colliders, then self-collision
    bool hold_in_hand_after_step(StepInProgress& step, bool judge_grip);  // false: it slipped
    std::size_t tear_after_step();                                        // springs torn
    std::optional<std::string> check_guards(const StepInProgress& step, std::size_t springs_torn);

    Scene scene_;
    Cloth cloth_;
    ForceField field_;
    Integrator integrator_;
    double dt_;
    IntegratorWorkspace workspace_;
    std::shared_ptr<WorkerPool> pool_;  // shared by copies, which are never stepped at once
    Grab grab_;
    std::vector<Collider> colliders_;        // the scene's, then the floor if it has one
    double floor_height_ = 0.0;              // m, set by reset()
    std::vector<SpringGroup> switched_off_;  // families switched off, kept with their tears
    bool has_repulsion_ = false;             // any collider with the repulsion response
    std::optional<SelfCollision> self_collision_;
    std::vector<Vec3> grip_start_positions_;   // m, the state before a held implicit step,
    std::vector<Vec3> grip_start_velocities_;  // m/s, for taking it again if the grip slips
    DivergenceGuard divergence_guard_;
    EnergyGuard energy_guard_;
    RunawayTearingGuard tearing_guard_;
    std::vector<Spring> torn_;  // the springs the last step tore (kept: no allocation a step)
    double time_ = 0.0;
    std::uint64_t steps_taken_ = 0;
};

}  // namespace weft
