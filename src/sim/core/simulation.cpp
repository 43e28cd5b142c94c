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
    : scene_(scene), integrator_(scene.solver.integrator), dt_(scene.solver.dt) {
    if (auto why = unsupported_feature(scene)) throw std::invalid_argument(*why);
    set_options(options);
    set_thread_count(default_thread_count());
    reset();
}

void Simulation::set_options(const SimulationOptions& options) {
    workspace_.settings.options = options;
    workspace_.settings.options.kernel_build =
        std::min(options.kernel_build, supported_simd_level());
    divergence_guard_.set_kernel_build(workspace_.settings.options.kernel_build);
}

void Simulation::set_thread_count(int threads) {
    pool_ = std::make_shared<WorkerPool>(threads);
    workspace_.settings.pool = pool_.get();
}

void Simulation::reset() {
    cloth_ = build_cloth(scene_);
    switched_off_.clear();
    set_force_field(scene_.forces.gravity, scene_.forces.air_drag, scene_.forces.wind);
    workspace_.resize(cloth_.particle_count(), integrator_);
    workspace_.settings.pool = pool_.get();
    grab_ = Grab{};
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
    // The grip (grab.h). An explicit step cannot answer the hand within itself: its grip is
    // judged before the step, where the hand's move would leave the springs at the hand.
    // Implicit Euler's solve answers the hand, so its grip is judged after the solve: where
    // it slipped, the step is taken again from the same state without the hand. The solve
    // sees the grip too, and does not refine a try that failed past it (implicit_euler.cpp).
    if (!grab_.active()) return take_step(false);
    find_grip_springs(grab_, cloth_);
    prescribe_hand_motion(grab_, cloth_, dt_);
    if (integrator_ != Integrator::implicit_euler) {
        if (coming_grip_stretch(grab_, cloth_, dt_) <= grab_.grip_stretch) return take_step(false);
        let_go();
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
    let_go();
    report = take_step(false);
    report.hand_slipped = true;
    report.times.add(first_try);
    return report;
}

// What one step carries from phase to phase: the guard's sweep, kept through the
// corrections (sweep_watch.h), the work done on the fused step's rows, and what the
// corrections moved.
struct Simulation::StepInProgress {
    explicit StepInProgress(Simulation& simulation)
        : measured(simulation.cloth_.particle_count()),
          rows_work{simulation.colliders_,
                    simulation.workspace_.scratch.next_positions,
                    simulation.workspace_.scratch.next_velocities,
                    simulation.cloth_,
                    nullptr,
                    simulation.self_collision_ ? &*simulation.self_collision_ : nullptr,
                    measured} {}
    bool held = false;                   // the hand holds the cloth through the step
    bool check_runaway_stretch = false;  // the divergence guard's test (not with tearing)
    std::optional<SweepWatch> watch;
    SweepWatch* watching = nullptr;  // the watch, while its sweep stands
    SelfCollision::MeasuredMoves measured;
    OnSteppedRows rows_work;
    RowsSteppedWork after_rows{OnSteppedRows::run, &rows_work};
    std::size_t corrections = 0;  // particles the corrections after the step moved
};

StepReport Simulation::take_step(bool judge_grip) {
    StepReport report;
    PhaseClock clock(profiling());
    StepInProgress step(*this);
    begin_step(step, report);
    if (judge_grip) {
        field_.grip_springs = grab_.grip_springs;
        field_.grip_stretch = grab_.grip_stretch;
    }
    integrate(integrator_, cloth_, field_, dt_, workspace_);
    clear_step_field();
    clock.lap(report.times.integrate);
    report.times.implicit = workspace_.statistics.implicit_times;
    if (judge_grip && workspace_.statistics.implicit_hand_let_go) {
        report.hand_slipped = true;  // the solve found the grip slipped; step() retakes it
        return report;
    }
    limit_strain_after_step(step);
    clock.lap(report.times.strain_limit);
    report.contacts = resolve_contacts(step);
    if (step.held && !hold_in_hand_after_step(step, judge_grip)) {
        report.hand_slipped = true;  // step() takes it again without the hand
        clock.lap(report.times.contacts);
        return report;
    }
    clock.lap(report.times.contacts);
    time_ += dt_;
    ++steps_taken_;
    report.springs_torn = tear_after_step();
    clock.lap(report.times.tearing);
    report.divergence = check_guards(step, report.springs_torn);
    clock.lap(report.times.guards);
    return report;
}

void Simulation::begin_step(StepInProgress& step, StepReport& report) {
    workspace_.statistics.implicit_times = {};
    // The hand's particles get the velocity that takes them where the hand goes (grab.h).
    // The field points at them only for the step, so a copied Simulation never holds a
    // pointer into another one.
    step.held = report.held = grab_.active();
    if (step.held) start_hand_motion(grab_, cloth_, dt_);
    field_.held = grab_.particles;
    // Gusts: the wind of this step's start (gusts.h), held through the step.
    if (scene_.forces.gust > 0.0)
        field_.wind = to_vec3(gusty_wind(scene_.forces.wind, scene_.forces.gust, time_));
    field_.colliders =
        has_repulsion_ ? std::span<const Collider>(colliders_) : std::span<const Collider>();
    field_.solids = colliders_;
    // The guard's sweep, done by a fused step on its way and kept through the corrections
    // after it; what the step's own sweep found is added once it is done.
    step.check_runaway_stretch = !scene_.tear_max_stretch;
    OnTheWay& way = workspace_.on_the_way;
    way.sweep_request = divergence_guard_.sweep_request(cloth_, step.check_runaway_stretch);
    if (way.sweep_request) {
        step.watch.emplace(*way.sweep_request);
        step.rows_work.watch = &*step.watch;
    }
    // The contacts and self-collision's measure ride on the fused step's rows when nothing
    // comes between them and the step (the strain limiter would). Self-collision judges the
    // step by where each particle went from (self_collision.h).
    const bool on_rows =
        !scene_.strain_limit_max_strain && (!colliders_.empty() || self_collision_);
    way.after_rows = on_rows ? &step.after_rows : nullptr;
    way.keep_start_positions = self_collision_.has_value();
}

void Simulation::clear_step_field() {
    field_.held = {};
    field_.grip_springs = {};
    field_.grip_stretch = 0.0;
    field_.colliders = {};
    field_.solids = {};
    workspace_.on_the_way.after_rows = nullptr;
}

void Simulation::limit_strain_after_step(StepInProgress& step) {
    std::size_t strain_corrections = 0;
    if (scene_.strain_limit_max_strain)
        strain_corrections = limit_strain(cloth_, *scene_.strain_limit_max_strain, dt_);
    // Position Verlet's history is its previous positions, and the limiter's correction
    // moves a particle by Δx and changes its velocity by Δx / h: exactly what keeping
    // x_{n-1} makes of it (Provot's correction was made for Verlet). Restarting the history
    // instead, every step the limit acts, turns the method into forward Euler in velocity,
    // which gains energy: course_pinned.toml, held at the limit every step, vibrated at
    // 3 m/s rms (70 J of kinetic energy in a 15 kg sheet at rest) at any dt.
    if (integrator_ != Integrator::verlet) step.corrections += strain_corrections;
    // The step's sweep for the guard stays valid through the contacts and self-collision if
    // they check what they move (sweep_watch.h); the strain limiter moves too many particles
    // for that, and after its corrections the guard sweeps again.
    if (step.watch && workspace_.on_the_way.sweep_result && strain_corrections == 0) {
        step.watch->add(*workspace_.on_the_way.sweep_result);
        step.watching = &*step.watch;
    }
}

std::size_t Simulation::resolve_contacts(StepInProgress& step) {
    const OnTheWay& way = workspace_.on_the_way;
    std::size_t contacts = 0;
    if (way.rows_done)
        contacts += step.rows_work.contacts.load(std::memory_order_relaxed);
    else if (!colliders_.empty())
        contacts += resolve_impulse_contacts(colliders_, cloth_, pool_.get(), step.watching);
    // Self-collision goes after the contacts and keeps the particles out of the solids itself.
    if (self_collision_)
        contacts +=
            self_collision_->resolve(cloth_, colliders_, pool_.get(), way.start_positions,
                                     step.watching, way.rows_done ? &step.measured : nullptr);
    step.corrections += contacts;
    return contacts;
}

bool Simulation::hold_in_hand_after_step(StepInProgress& step, bool judge_grip) {
    // Whatever the step and the corrections did to the held particles, they end it where the
    // hand put them. Not a correction for the Verlets' history: their previous positions are
    // where the hand had them, which is how the hand moved them.
    hold_in_hand(grab_, cloth_);
    if (judge_grip && largest_grip_stretch(grab_, cloth_) > grab_.grip_stretch) return false;
    if (step.watching)
        for (const std::uint32_t p : grab_.particles)
            step.watching->check(p, cloth_.positions[p], cloth_.velocities[p]);
    return true;
}

std::size_t Simulation::tear_after_step() {
    if (!scene_.tear_max_stretch) return 0;
    torn_.clear();
    return tear_overstretched_springs(cloth_, *scene_.tear_max_stretch, &torn_);
}

std::optional<std::string> Simulation::check_guards(const StepInProgress& step,
                                                    std::size_t springs_torn) {
    // Forces changed with the topology; the Verlets' carried acceleration is stale.
    if (springs_torn || step.corrections) workspace_.history.valid = false;
    // A sweep done during the step stands if nothing has moved a particle since, or if what
    // did checked the particles it moved. With tearing on, a runaway spring breaks instead of
    // stretching without bound, so only non-finite values count as divergence.
    std::optional<ParticleSweep> swept;
    if (step.watching)
        swept = step.watching->result();
    else if (step.corrections == 0 && !step.held)
        swept = workspace_.on_the_way.sweep_result;
    std::optional<std::string> divergence =
        divergence_guard_.check(cloth_, step.check_runaway_stretch, pool_.get(), swept);
    // With tearing on, an unstable step shreds the cloth rather than diverge (runaway_tearing.h).
    if (!divergence && scene_.tear_max_stretch)
        divergence = tearing_guard_.check(cloth_, torn_, time_, grab_);
    if (!divergence)
        divergence = energy_guard_.check(cloth_, field_, time_, grab_.active(), pool_.get());
    return divergence;
}

void Simulation::set_integrator(Integrator integrator) {
    if (!step_function(integrator)) throw std::invalid_argument("integrator not available");
    integrator_ = integrator;
    scene_.solver.integrator = integrator;  // scene() follows, so reset and saving keep it
    workspace_.resize(cloth_.particle_count(), integrator);  // the new method's scratch only
}

void Simulation::set_dt(double dt) {
    dt_ = dt;
    scene_.solver.dt = dt;
    workspace_.history.valid = false;
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
    workspace_.history.valid = false;  // the carried accelerations came from the old forces
}

void Simulation::set_family_enabled(SpringFamily family, bool enabled) {
    energy_guard_.forget();   // the energy is measured against other terms now
    tearing_guard_.forget();  // and the sheet's share against another count of springs
    SpringFamilySpec& spec = family_spec(scene_, family);
    if (family == SpringFamily::structural || spec.enabled == enabled) return;
    spec.enabled = enabled;
    workspace_.history.valid = false;
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
    workspace_.history.valid = false;
}

void Simulation::set_particle_mass(double mass) {
    energy_guard_.forget();  // the energy is measured against other terms now
    scene_.cloth.particle_mass = mass;
    ClothTopology& topology = cloth_.edit_topology();
    for (std::size_t p = 0; p < cloth_.particle_count(); ++p) {
        topology.masses[p] = mass;
        if (topology.inverse_masses[p] != 0.0) topology.inverse_masses[p] = 1.0 / mass;
    }
    workspace_.history.valid = false;
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
        workspace_.history.valid = false;
    }
    scene_.camera = wanted.camera;
    scene_.name = wanted.name;
}

void Simulation::start_grab(Grab grab) {
    grab_ = std::move(grab);
    grab_.last_pull_time = time_;
    // The held particles' velocities change at once: carried history no longer fits them.
    workspace_.history.valid = false;
}

void Simulation::pull_to(const Vec3& target) {
    if (grab_.active()) move_hand(grab_, target, time_, dt_);
}

void Simulation::let_go() {
    grab_ = Grab{};
    workspace_.history.valid = false;
    // The energy guard measures from where the hand lets go: what the hand put in since its
    // last check is the cloth's now (energy_guard.h).
    energy_guard_.forget();
}

void Simulation::set_pinned(std::size_t particle, bool pinned) {
    energy_guard_.forget();  // the energy is measured against other terms now
    weft::set_pinned(cloth_, particle, pinned);
    workspace_.history.valid = false;
}

void Simulation::release_all_pins() {
    energy_guard_.forget();  // the energy is measured against other terms now
    while (!cloth_.topology().pinned.empty())
        weft::set_pinned(cloth_, cloth_.topology().pinned.back(), false);
    workspace_.history.valid = false;
}

Cloth& Simulation::edit_cloth() {
    workspace_.history.valid = false;
    divergence_guard_.forget();  // the caller may change more than positions
    energy_guard_.forget();
    tearing_guard_.forget();
    return cloth_;
}

}  // namespace weft
