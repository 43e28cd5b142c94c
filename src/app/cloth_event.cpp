#include "app/cloth_event.h"

#include <algorithm>

#include "sim/build/topology_edits.h"
#include "sim/interaction/grab.h"

namespace weft::app {

const char* event_kind_name(ClothEvent::Kind kind) {
    switch (kind) {
        case ClothEvent::Kind::grab:
            return "grab";
        case ClothEvent::Kind::pull:
            return "pull";
        case ClothEvent::Kind::let_go:
            return "let-go";
        case ClothEvent::Kind::cut:
            return "cut";
        case ClothEvent::Kind::pin:
            return "pin";
        case ClothEvent::Kind::unpin:
            return "unpin";
        case ClothEvent::Kind::release_pins:
            return "release-pins";
        case ClothEvent::Kind::edit:
            return "edit";
        case ClothEvent::Kind::parameters:
            return "parameters";
        case ClothEvent::Kind::reset:
            return "reset";
    }
    return "unknown";
}

namespace {

// Runs `simulation` on `wanted` from here on: live where only parameters differ, as a new
// simulation where the cloth or a collider's shape does.
EventResult run_with(Simulation& simulation, Scene wanted, const SolverSpec* keep_solver) {
    if (keep_solver) wanted.solver = *keep_solver;
    if (!Simulation::live_changeable(simulation.scene(), wanted)) {
        simulation = Simulation(wanted);
        return EventResult::rebuilt;
    }
    simulation.set_parameters(wanted);
    return EventResult::applied;
}

}  // namespace

EventResult apply_event(Simulation& simulation, const ClothEvent& event,
                        const SolverSpec* keep_solver) {
    const std::size_t particles = simulation.cloth().particle_count();
    switch (event.kind) {
        case ClothEvent::Kind::grab:
            if (event.hit.particle < particles)
                simulation.start_grab(grab_cloth(simulation.cloth(), event.hit, event.radius));
            return EventResult::applied;
        case ClothEvent::Kind::pull:
            if (simulation.grab().active()) simulation.pull_to(event.target);
            return EventResult::applied;
        case ClothEvent::Kind::let_go:
            if (simulation.grab().active()) simulation.let_go();
            return EventResult::applied;
        case ClothEvent::Kind::cut:
            if (!event.springs.empty())
                simulation.cut_springs([&](const Spring& s) {
                    return std::binary_search(event.springs.begin(), event.springs.end(),
                                              edge_key(s.i, s.j));
                });
            return EventResult::applied;
        case ClothEvent::Kind::pin:
        case ClothEvent::Kind::unpin:
            if (event.particle < particles)
                simulation.set_pinned(event.particle, event.kind == ClothEvent::Kind::pin);
            return EventResult::applied;
        case ClothEvent::Kind::release_pins:
            simulation.release_all_pins();
            return EventResult::applied;
        case ClothEvent::Kind::edit: {
            Scene wanted = simulation.scene();
            if (apply_scene_edits(wanted, event.edits)) return EventResult::refused;
            return run_with(simulation, std::move(wanted), keep_solver);
        }
        case ClothEvent::Kind::parameters:
            if (!event.scene) return EventResult::refused;
            return run_with(simulation, *event.scene, keep_solver);
        case ClothEvent::Kind::reset:
            simulation.reset();
            return EventResult::applied;
    }
    return EventResult::applied;
}

}  // namespace weft::app
