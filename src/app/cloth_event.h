// ClothEvent: one thing the user did to the simulation, in the simulation's terms (a grab
// at a point of the cloth, a pull towards a point in space, the springs a stroke cut, a
// parameter set) rather than in pixels. The window turns mouse and keys into events on the
// run under the cursor; the same event then goes to every run shown side by side, and to
// the session recording, which replays it at the same step to the same result, bit for bit.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sim/core/simulation.h"
#include "sim/interaction/picking.h"
#include "sim/scene/scene_edit.h"

namespace weft::app {

struct ClothEvent {
    enum class Kind : std::uint8_t {
        grab,          // hit, radius: take hold of the cloth
        pull,          // target: move the held point
        let_go,        // let go of the cloth; the cloth keeps its velocity
        cut,           // springs: remove these springs (edge keys) and their triangles
        pin,           // particle
        unpin,         // particle
        release_pins,  // free every pinned particle
        edit,          // edits: typed parameter changes (scene_edit.h), all or none
        parameters,    // scene: a whole scene to run with; only in format-1 recordings
        reset,         // back to the scene's start
    };
    Kind kind = Kind::let_go;
    RayHit hit{};                        // grab
    double radius = 0.0;                 // grab, m
    Vec3 target{0.0};                    // pull, m
    std::vector<std::uint64_t> springs;  // cut: edge_key(i, j) of each spring, ascending
    std::uint32_t particle = 0;          // pin, unpin
    std::vector<SceneEdit> edits;        // edit
    std::shared_ptr<const Scene> scene;  // parameters (checked when read)
};

const char* event_kind_name(ClothEvent::Kind kind);

// An event with no fields of its own (let_go, release_pins, reset).
inline ClothEvent plain_event(ClothEvent::Kind kind) {
    ClothEvent event;
    event.kind = kind;
    return event;
}

enum class EventResult {
    applied,  // done (or did not fit this simulation and was ignored)
    rebuilt,  // an edit changed the cloth (its grid, mass): `simulation` is a new one
    refused,  // an edit the scene rules refuse: nothing changed
};

// Applies the event to `simulation`. An event that does not fit it (a particle it does not
// have) is ignored. An edit or parameters event keeps `keep_solver`'s integrator and dt if
// given: runs side by side share the material and the forces but each keeps its own method.
EventResult apply_event(Simulation& simulation, const ClothEvent& event,
                        const SolverSpec* keep_solver = nullptr);

}  // namespace weft::app
