#include "sim/core/simulation.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>

#include "sim/build/cloth_builder.h"
#include "sim/collision/floor.h"
#include "sim/constraints/strain_limit.h"
#include "sim/constraints/tearing.h"
#include "sim/core/gusts.h"
#include "sim/guards/divergence.h"
#include "sim/guards/sweep_watch.h"

namespace weft {
namespace {

Vec3 to_vec3(const Vec3d& v) {
    return {v[0], v[1], v[2]};
}

// The contacts and self-collision's measure of the step's moves, done on the rows the fused
// step has just written by the thread that wrote them (grid_force_pass.h): one hand-off to
// the threads instead of three, with the particles still in cache. The same bits as the
// separate passes: a particle's contacts depend on it alone, and the measures are minima,
// maxima and "and"s, exact in any order.
struct OnSteppedRows {
    std::span<const Collider> colliders;  // the impulse ones act
    std::vector<Vec3>& positions;         // m: the new state, in the fused step's buffers
    std::vector<Vec3>& velocities;        // m/s
    const Cloth& cloth;                   // still at the step's start
    SweepWatch* watch;
    const SelfCollision* self_collision;  // none: nothing to measure
    SelfCollision::MeasuredMoves& moves;
    std::atomic<std::size_t> contacts{0};

    static void run(void* context, std::size_t begin, std::size_t end) {
        auto& work = *static_cast<OnSteppedRows*>(context);
        if (!work.colliders.empty())
            work.contacts.fetch_add(
                resolve_impulse_contacts(
                    work.colliders, work.positions.data(), work.velocities.data(),
                    work.cloth.topology().inverse_masses.data(), begin, end, work.watch),
                std::memory_order_relaxed);
        if (work.self_collision)
            work.self_collision->measure_step_moves(
                work.positions.data(), work.cloth.positions.data(), begin, end, work.moves);
    }
};

}  // namespace

std::optional<std::string> Simulation::unsupported_feature(const Scene& /*scene*/) {
    // Every scene the loader accepts is modelled now; the check stays as the one place a
    // feature the format knows but this build lacks would be refused.
    return std::nullopt;
}

Simulation::Simulation(const Scene& scene, const SimulationOptions& options)
    : scene_(scene),
      integrator_(scene.solver.integrator),
      step_function_(step_function(scene.solver.integrator)),
      dt_(scene.solver.dt) {
    if (auto why = unsupported_feature(scene)) throw std::invalid_argument(*why);
    set_options(options);
    set_thread_count(default_thread_count());
    reset();
}

void Simulation::set_options(const SimulationOptions& options) {
    workspace_.options = options;
    workspace_.options.kernel_build = std::min(options.kernel_build, supported_simd_level());
    divergence_guard_.set_kernel_build(workspace_.options.kernel_build);
}

void Simulation::set_thread_count(int threads) {
    pool_ = std::make_shared<WorkerPool>(threads);
    workspace_.pool = pool_.get();
}

void Simulation::reset() {
    cloth_ = build_cloth(scene_);
    switched_off_.clear();
    set_force_field(scene_.forces.gravity, scene_.forces.air_drag, scene_.forces.wind);
    workspace_.resize(cloth_.particle_count(), integrator_);
    workspace_.pool = pool_.get();
    drag_ = DragHandle{};
    // The floor goes under the cloth as it starts, and stays there through every edit.
    floor_height_ = floor_height(cloth_, make_colliders(scene_.colliders));
    build_colliders();
    self_collision_.reset();
    divergence_guard_.forget();
    energy_guard_.forget();
    tearing_guard_.forget();
    if (scene_.self_collision_thickness) self_collision_.emplace(*scene_.self_collision_thickness);
    time_ = 0.0;
    steps_taken_ = 0;
}

StepReport Simulation::step() {
    // The grip (drag.h). An explicit step cannot answer the hand within itself: its grip is
    // judged before the step, where the hand's move would leave the springs at the hand.
    // Implicit Euler's solve answers the hand, so its grip is judged after the solve: where
    // it slipped, the step is taken again from the same state without the hand.
    if (!drag_.active()) return take_step(false);
    find_grip_springs(drag_, cloth_);
    prescribe_hand_motion(drag_, cloth_, dt_);
    if (integrator_ != Integrator::implicit_euler) {
        if (coming_grip_stretch(drag_, cloth_, dt_) <= drag_.grip_stretch) return take_step(false);
        end_drag();
        StepReport report = take_step(false);
        report.hand_slipped = true;
        return report;
    }
    grip_start_positions_ = cloth_.positions;  // no allocation after the first held step
    grip_start_velocities_ = cloth_.velocities;
    StepReport report = take_step(true);
    if (!report.hand_slipped) return report;
    const StepTimes first_try = report.times;
    cloth_.positions = grip_start_positions_;
    cloth_.velocities = grip_start_velocities_;
    end_drag();
    report = take_step(false);
    report.hand_slipped = true;
    report.times.add(first_try);
    return report;
}

StepReport Simulation::take_step(bool judge_grip) {
    StepReport report;
    PhaseClock clock(profiling_);
    workspace_.profiling = profiling_;
    workspace_.implicit_times = {};
    // The hand's particles get the velocity that takes them where the hand goes (drag.h).
    // The field points at them only for the step, so a copied Simulation never holds a
    // pointer into another one.
    const bool held = drag_.active();
    report.held = held;
    if (held) start_hand_motion(drag_, cloth_, dt_);
    field_.held = drag_.particles;
    // Gusts: the wind of this step's start (gusts.h), held through the step.
    if (scene_.forces.gust > 0.0)
        field_.wind = to_vec3(gusty_wind(scene_.forces.wind, scene_.forces.gust, time_));
    field_.colliders =
        has_repulsion_ ? std::span<const Collider>(colliders_) : std::span<const Collider>();
    field_.solids = colliders_;
    const bool check_runaway_stretch = !scene_.tear_max_stretch;
    workspace_.sweep_request = divergence_guard_.sweep_request(cloth_, check_runaway_stretch);
    workspace_.sweep_result.reset();
    // The guard's sweep, kept through the corrections after the step (sweep_watch.h); what
    // the step's own sweep found is added once it is done.
    std::optional<SweepWatch> watch;
    if (workspace_.sweep_request) watch.emplace(*workspace_.sweep_request);
    // The contacts and self-collision's measure ride on the fused step's rows when nothing
    // comes between them and the step (the strain limiter would).
    const bool on_rows =
        !scene_.strain_limit_max_strain && (!colliders_.empty() || self_collision_);
    SelfCollision::MeasuredMoves measured(cloth_.particle_count());
    OnSteppedRows rows_work{
        colliders_, workspace_.next_positions, workspace_.next_velocities,
        cloth_,     watch ? &*watch : nullptr, self_collision_ ? &*self_collision_ : nullptr,
        measured};
    const RowsSteppedWork after_rows{OnSteppedRows::run, &rows_work};
    bool corrected_on_rows = false;
    // Self-collision judges the step by where each particle went from (self_collision.h).
    // The fused grid step leaves those positions in its output buffer; any other step is
    // taken in place, so they are copied first.
    std::span<const Vec3> step_start;
    if (integrator_ == Integrator::symplectic_euler &&
        step_symplectic_euler_fused(cloth_, field_, dt_, workspace_,
                                    on_rows ? &after_rows : nullptr)) {
        step_start = workspace_.next_positions;
        corrected_on_rows = on_rows;
    } else {
        if (self_collision_) {
            step_start_ = cloth_.positions;
            step_start = step_start_;
        }
        step_function_(cloth_, field_, dt_, workspace_);
    }
    field_.held = {};
    field_.colliders = {};
    field_.solids = {};
    clock.lap(report.times.integrate);
    report.times.implicit = workspace_.implicit_times;
    // Corrections of positions and velocities after the step; any of them makes the history
    // the Verlets carry stale.
    std::size_t corrections = 0;
    std::size_t strain_corrections = 0;
    if (scene_.strain_limit_max_strain)
        strain_corrections = limit_strain(cloth_, *scene_.strain_limit_max_strain, dt_);
    // Position Verlet's history is its previous positions, and the limiter's correction
    // moves a particle by Δx and changes its velocity by Δx / h: exactly what keeping
    // x_{n-1} makes of it (Provot's correction was made for Verlet). Restarting the history
    // instead, every step the limit acts, turns the method into forward Euler in velocity,
    // which gains energy: course_pinned.toml, held at the limit every step, vibrated at
    // 3 m/s rms (70 J of kinetic energy in a 15 kg sheet at rest) at any dt.
    if (integrator_ != Integrator::verlet) corrections += strain_corrections;
    clock.lap(report.times.strain_limit);
    // The step's sweep for the guard stays valid through the contacts and self-collision if
    // they check what they move (sweep_watch.h); the strain limiter moves too many particles
    // for that, and after its corrections the guard sweeps again.
    SweepWatch* watching = nullptr;
    if (watch && workspace_.sweep_result && strain_corrections == 0) {
        watch->add(*workspace_.sweep_result);
        watching = &*watch;
    }
    if (corrected_on_rows)
        report.contacts += rows_work.contacts.load(std::memory_order_relaxed);
    else if (!colliders_.empty())
        report.contacts += resolve_impulse_contacts(colliders_, cloth_, pool_.get(), watching);
    // Self-collision goes after the contacts and keeps the particles out of the solids itself.
    if (self_collision_)
        report.contacts +=
            self_collision_->resolve(cloth_, colliders_, pool_.get(), step_start, watching,
                                     corrected_on_rows ? &measured : nullptr);
    corrections += report.contacts;
    // Whatever the step and the corrections did to the held particles, they end it where the
    // hand put them. Not a correction for the Verlets' history: their previous positions are
    // where the hand had them, which is how the hand moved them.
    if (held) {
        hold_in_hand(drag_, cloth_);
        if (judge_grip && largest_grip_stretch(drag_, cloth_) > drag_.grip_stretch) {
            report.hand_slipped = true;  // step() takes it again without the hand
            clock.lap(report.times.contacts);
            return report;
        }
        if (watching)
            for (const std::uint32_t p : drag_.particles)
                watching->check(p, cloth_.positions[p], cloth_.velocities[p]);
    }
    clock.lap(report.times.contacts);
    time_ += dt_;
    ++steps_taken_;
    if (scene_.tear_max_stretch) {
        torn_.clear();
        report.springs_torn = tear_overstretched_springs(cloth_, *scene_.tear_max_stretch, &torn_);
    }
    clock.lap(report.times.tearing);
    // Forces changed with the topology; the Verlets' carried acceleration is stale.
    if (report.springs_torn || corrections) workspace_.history_valid = false;
    // With tearing on, a runaway spring breaks instead of stretching without bound, so only
    // non-finite values count as divergence.
    // A sweep done during the step stands if nothing has moved a particle since, or if what
    // did checked the particles it moved.
    std::optional<ParticleSweep> swept;
    if (watching)
        swept = watching->result();
    else if (corrections == 0 && !held)
        swept = workspace_.sweep_result;
    report.divergence = divergence_guard_.check(cloth_, check_runaway_stretch, pool_.get(), swept);
    // With tearing on, an unstable step shreds the cloth rather than diverge (runaway_tearing.h).
    if (!report.divergence && scene_.tear_max_stretch)
        report.divergence = tearing_guard_.check(cloth_, torn_, time_, drag_);
    if (!report.divergence)
        report.divergence = energy_guard_.check(cloth_, field_, time_, drag_.active(), pool_.get());
    clock.lap(report.times.guards);
    return report;
}

void Simulation::set_integrator(Integrator integrator) {
    StepFunction function = step_function(integrator);
    if (!function) throw std::invalid_argument("integrator not available");
    integrator_ = integrator;
    scene_.solver.integrator = integrator;  // scene() follows, so reset and saving keep it
    step_function_ = function;
    workspace_.resize(cloth_.particle_count(), integrator);  // the new method's scratch only
}

void Simulation::set_dt(double dt) {
    dt_ = dt;
    scene_.solver.dt = dt;
    workspace_.history_valid = false;
}

namespace {

template <class SceneType>  // Scene or const Scene
auto& family_spec(SceneType& scene, SpringFamily family) {
    return family == SpringFamily::structural ? scene.structural
           : family == SpringFamily::shear    ? scene.shear
                                              : scene.bend;
}

}  // namespace

void Simulation::set_spring_material(SpringFamily family, double stiffness, double damping) {
    energy_guard_.forget();  // the energy is measured against other terms now
    SpringFamilySpec& spec = family_spec(scene_, family);
    spec.stiffness = stiffness;
    spec.damping = damping;
    for (auto* groups : {&cloth_.edit_topology().spring_groups, &switched_off_}) {
        for (SpringGroup& group : *groups) {
            if (group.family != family) continue;
            group.stiffness = stiffness;
            group.damping = damping;
        }
    }
    workspace_.history_valid = false;  // the carried accelerations came from the old forces
}

void Simulation::set_family_enabled(SpringFamily family, bool enabled) {
    energy_guard_.forget();   // the energy is measured against other terms now
    tearing_guard_.forget();  // and the sheet's share against another count of springs
    SpringFamilySpec& spec = family_spec(scene_, family);
    if (family == SpringFamily::structural || spec.enabled == enabled) return;
    spec.enabled = enabled;
    workspace_.history_valid = false;
    if (!enabled) {
        if (auto taken = take_spring_family(cloth_, family))
            switched_off_.push_back(std::move(*taken));
        return;
    }
    auto kept = std::find_if(switched_off_.begin(), switched_off_.end(),
                             [&](const SpringGroup& g) { return g.family == family; });
    if (kept != switched_off_.end()) {
        SpringGroup group = std::move(*kept);
        switched_off_.erase(kept);
        add_spring_family(cloth_, std::move(group));
        return;
    }
    // Never built: as the builder makes it for the intact sheet, with the current material.
    Cloth intact = build_cloth(scene_);
    std::optional<SpringGroup> fresh = take_spring_family(intact, family);
    if (fresh) add_spring_family(cloth_, std::move(*fresh));
}

void Simulation::set_force_field(const Vec3d& gravity, double air_drag, const Vec3d& wind) {
    energy_guard_.forget();  // the energy is measured against other terms now
    scene_.forces.gravity = gravity;
    scene_.forces.air_drag = air_drag;
    scene_.forces.wind = wind;
    field_.gravity = to_vec3(gravity);
    field_.air_drag = air_drag;
    field_.wind = to_vec3(wind);
    workspace_.history_valid = false;
}

void Simulation::set_particle_mass(double mass) {
    energy_guard_.forget();  // the energy is measured against other terms now
    scene_.cloth.particle_mass = mass;
    ClothTopology& topology = cloth_.edit_topology();
    for (std::size_t p = 0; p < cloth_.particle_count(); ++p) {
        topology.masses[p] = mass;
        if (topology.inverse_masses[p] != 0.0) topology.inverse_masses[p] = 1.0 / mass;
    }
    workspace_.history_valid = false;
}

void Simulation::set_tear_limit(std::optional<double> max_stretch) {
    // A lower limit breaks every spring already past it on the next step, all over the
    // sheet: the user's choice, not the motion running away.
    if (max_stretch && (!scene_.tear_max_stretch || *max_stretch < *scene_.tear_max_stretch))
        tearing_guard_.ignore_next_step();
    scene_.tear_max_stretch = max_stretch;
}

void Simulation::set_strain_limit(std::optional<double> max_strain) {
    energy_guard_.forget();  // the energy is measured against other terms now
    scene_.strain_limit_max_strain = max_strain;
}

void Simulation::build_colliders() {
    colliders_ = make_colliders(scene_.colliders);
    if (scene_.floor_enabled && std::none_of(colliders_.begin(), colliders_.end(), is_ground_plane))
        colliders_.push_back(floor_collider(floor_height_));
    has_repulsion_ = std::any_of(colliders_.begin(), colliders_.end(), [](const Collider& c) {
        return c.response == ContactResponse::repulsion;
    });
}

bool Simulation::live_changeable(const Scene& running, const Scene& wanted) {
    if (!(running.cloth == wanted.cloth) || running.colliders.size() != wanted.colliders.size())
        return false;
    for (std::size_t c = 0; c < running.colliders.size(); ++c)
        if (running.colliders[c].type != wanted.colliders[c].type) return false;
    return true;
}

void Simulation::set_parameters(const Scene& wanted) {
    energy_guard_.forget();  // the energy is measured against other terms now
    if (!live_changeable(scene_, wanted))
        throw std::invalid_argument("set_parameters: the cloth or its colliders' shapes differ");
    if (wanted.solver.integrator != integrator_) set_integrator(wanted.solver.integrator);
    if (wanted.solver.dt != dt_) set_dt(wanted.solver.dt);
    for (SpringFamily family :
         {SpringFamily::structural, SpringFamily::shear, SpringFamily::bend}) {
        const SpringFamilySpec& want = family_spec(wanted, family);
        const SpringFamilySpec& have = family_spec(scene_, family);
        if (want.stiffness != have.stiffness || want.damping != have.damping)
            set_spring_material(family, want.stiffness, want.damping);
        if (want.enabled != have.enabled) set_family_enabled(family, want.enabled);
    }
    if (wanted.cloth.particle_mass != scene_.cloth.particle_mass)
        set_particle_mass(wanted.cloth.particle_mass);
    if (!(wanted.forces == scene_.forces)) {
        set_force_field(wanted.forces.gravity, wanted.forces.air_drag, wanted.forces.wind);
        scene_.forces.gust = wanted.forces.gust;
    }
    set_tear_limit(wanted.tear_max_stretch);
    set_strain_limit(wanted.strain_limit_max_strain);
    if (wanted.self_collision_thickness != scene_.self_collision_thickness) {
        scene_.self_collision_thickness = wanted.self_collision_thickness;
        self_collision_.reset();
        if (wanted.self_collision_thickness)
            self_collision_.emplace(*wanted.self_collision_thickness);
    }
    if (wanted.colliders != scene_.colliders || wanted.floor_enabled != scene_.floor_enabled) {
        scene_.colliders = wanted.colliders;
        scene_.floor_enabled = wanted.floor_enabled;
        build_colliders();
        workspace_.history_valid = false;
    }
    scene_.camera = wanted.camera;
    scene_.name = wanted.name;
}

void Simulation::start_drag(DragHandle drag) {
    drag_ = std::move(drag);
    drag_.last_pull_time = time_;
    // The held particles' velocities change at once: carried history no longer fits them.
    workspace_.history_valid = false;
}

void Simulation::move_drag_target(const Vec3& target) {
    if (drag_.active()) move_hand(drag_, target, time_, dt_);
}

void Simulation::end_drag() {
    drag_ = DragHandle{};
    workspace_.history_valid = false;
    // The energy guard measures from where the hand lets go: what the hand put in since its
    // last check is the cloth's now (energy_guard.h).
    energy_guard_.forget();
}

void Simulation::set_pinned(std::size_t particle, bool pinned) {
    energy_guard_.forget();  // the energy is measured against other terms now
    weft::set_pinned(cloth_, particle, pinned);
    workspace_.history_valid = false;
}

void Simulation::release_all_pins() {
    energy_guard_.forget();  // the energy is measured against other terms now
    while (!cloth_.topology().pinned.empty())
        weft::set_pinned(cloth_, cloth_.topology().pinned.back(), false);
    workspace_.history_valid = false;
}

Cloth& Simulation::edit_cloth() {
    workspace_.history_valid = false;
    divergence_guard_.forget();  // the caller may change more than positions
    energy_guard_.forget();
    tearing_guard_.forget();
    return cloth_;
}

}  // namespace weft
