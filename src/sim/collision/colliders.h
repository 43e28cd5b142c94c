// Colliders: spheres and planes the cloth drapes over, with two responses.
//
//  impulse    after each step, a particle found inside is moved to the surface; its normal
//             velocity is reflected with the restitution (0: perfectly inelastic, 1:
//             elastic) and its tangential velocity reduced by Coulomb friction: the
//             tangential change is at most friction × the normal change, so a particle
//             slides until friction has taken its tangential speed.
//  repulsion  a stiff penalty force along the normal inside a thin contact layer, part of
//             the force pass (every integrator sees it at every stage), with a dashpot that
//             makes the contact critically damped and regularised Coulomb friction.
//
// A scene without colliders has none of this: no list, no pass.
#pragma once

#include <span>
#include <vector>

#include "parallel/worker_pool.h"
#include "sim/core/cloth.h"
#include "sim/scene/scene.h"

namespace weft {

class SweepWatch;  // sweep_watch.h

struct Collider {
    ColliderType type = ColliderType::sphere;
    Vec3 center{0.0};            // m, sphere
    double radius = 0.0;         // m, sphere
    Vec3 point{0.0};             // m, a point on the plane
    Vec3 normal{0.0, 1.0, 0.0};  // plane, unit, pointing to the free side
    ContactResponse response = ContactResponse::impulse;
    double restitution = 0.0;
    double friction = 0.0;
};

// Repulsion: contact layer thickness and the contact's natural frequency for a particle of
// mass m (stiffness m ω²). 300 rad/s keeps the contact stiff (sag m g / k = 0.1 mm) and
// inside the stability limit of every explicit method at the default step (h ω = 0.3).
inline constexpr double repulsion_layer = 0.01;               // m
inline constexpr double repulsion_angular_frequency = 300.0;  // rad/s

std::vector<Collider> make_colliders(const std::vector<ColliderSpec>& specs);

// Signed distance from x to the collider's surface (negative inside) and the outward normal.
double signed_distance(const Collider& collider, const Vec3& x, Vec3& outward_normal);

// Adds repulsion forces (N) for the colliders with that response.
void accumulate_repulsion_forces(std::span<const Collider> colliders, const Cloth& cloth,
                                 std::span<const Vec3> positions, std::span<const Vec3> velocities,
                                 std::span<Vec3> forces);

// Resolves impulse contacts on the cloth's current state; returns the number of contacts.
// Split between the pool's threads on large sheets; the same bits for any thread count.
// With a `watch`, each particle moved is checked for the divergence guard (sweep_watch.h).
std::size_t resolve_impulse_contacts(std::span<const Collider> colliders, Cloth& cloth,
                                     WorkerPool* pool = nullptr, SweepWatch* watch = nullptr);
// The same on the particles [begin, end) of a state held apart from a Cloth, on the calling
// thread: for a caller that does it beside other work on those particles (Simulation::step,
// on the rows the fused step has just written). Particles with inverse mass 0 stay.
std::size_t resolve_impulse_contacts(std::span<const Collider> colliders, Vec3* positions,
                                     Vec3* velocities, const double* inverse_masses,
                                     std::size_t begin, std::size_t end,
                                     SweepWatch* watch = nullptr);

// Moves particles found inside an impulse collider back onto its surface and removes their
// velocity into it, without friction or restitution: for passes that run after the contacts
// (self-collision) and may push a particle back into a solid. The contact's impulse was
// applied once already this step; this only keeps the solid impenetrable. Returns the
// particles moved.
std::size_t push_out_of_impulse_colliders(std::span<const Collider> colliders, Cloth& cloth,
                                          WorkerPool* pool = nullptr, SweepWatch* watch = nullptr);

}  // namespace weft
