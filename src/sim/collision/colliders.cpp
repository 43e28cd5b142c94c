#include "sim/collision/colliders.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>

#include "sim/collision/particle_pairs_sse2.h"
#include "sim/guards/sweep_watch.h"

namespace weft {
namespace {

Vec3 to_vec3(const Vec3d& v) {
    return {v[0], v[1], v[2]};
}

}  // namespace

std::vector<Collider> make_colliders(const std::vector<ColliderSpec>& specs) {
    std::vector<Collider> colliders;
    for (const ColliderSpec& spec : specs) {
        Collider c;
        c.type = spec.type;
        c.center = to_vec3(spec.center);
        c.radius = spec.radius;
        c.point = to_vec3(spec.point);
        c.normal = glm::normalize(to_vec3(spec.normal));
        c.response = spec.response;
        c.restitution = spec.restitution;
        c.friction = spec.friction;
        colliders.push_back(c);
    }
    return colliders;
}

double signed_distance(const Collider& collider, const Vec3& x, Vec3& outward_normal) {
    if (collider.type == ColliderType::plane) {
        outward_normal = collider.normal;
        return glm::dot(x - collider.point, collider.normal);
    }
    const Vec3 from_center = x - collider.center;
    const double distance = glm::length(from_center);
    // At the very centre any direction is outward; pick up.
    outward_normal = distance > 0.0 ? from_center / distance : Vec3(0.0, 1.0, 0.0);
    return distance - collider.radius;
}

void accumulate_repulsion_forces(std::span<const Collider> colliders, const Cloth& cloth,
                                 std::span<const Vec3> positions, std::span<const Vec3> velocities,
                                 std::span<Vec3> forces) {
    constexpr double omega = repulsion_angular_frequency;
    for (const Collider& collider : colliders) {
        if (collider.response != ContactResponse::repulsion) continue;
        for (std::size_t p = 0; p < positions.size(); ++p) {
            Vec3 n;
            const double depth = repulsion_layer - signed_distance(collider, positions[p], n);
            if (depth <= 0.0) continue;
            const double mass = cloth.topology().masses[p];
            const double normal_speed = glm::dot(velocities[p], n);
            // Spring m ω² depth and a critically damped dashpot on the normal speed; the
            // contact only pushes, never pulls.
            const double normal_force =
                std::max(0.0, mass * (omega * omega * depth - 2.0 * omega * normal_speed));
            Vec3 force = normal_force * n;
            // Coulomb friction, regularised over 1 mm/s so resting contact does not chatter.
            const Vec3 tangential = velocities[p] - normal_speed * n;
            const double sliding_speed = glm::length(tangential);
            if (sliding_speed > 0.0) {
                const double scale =
                    collider.friction * normal_force / std::max(sliding_speed, 1e-3);
                force -= scale * tangential;
            }
            forces[p] += force;
        }
    }
}

namespace {

// Bit k of the result: whether particle first + k may be inside the collider, for the
// particles [first, last) (at most 32). Exactly signed_distance's test for a plane, in its
// operations; for a sphere a superset of it, off by a margin far above rounding (clearly
// outside: no square root needed). No branch: two particles a round in SSE2
// (particle_pairs_sse2.h), each lane doing the scalar loop's operations in its order (so a
// plane's test stays exactly signed_distance's).
unsigned maybe_inside(const Collider& collider, const Vec3* x, std::size_t first,
                      std::size_t last) {
    unsigned maybe = 0;
    std::size_t p = first;
    const bool plane = collider.type == ColliderType::plane;
    const Vec3 a = plane ? collider.point : collider.center;  // m
    const Vec3 n = collider.normal;
    if (plane && n == Vec3(0.0, 1.0, 0.0)) {
        // A level floor: one comparison a particle. (dx 0 + dy 1) + dz 0 < 0 exactly when
        // y < a.y, for finite dx and dz (a zero term adds nothing, and a difference of doubles
        // has the sign of their order); an infinite or NaN dx or dz makes that sum NaN, and
        // the caller leaves a plane's NaN distance alone. So a superset of the test below,
        // with the same outcome.
        for (; p < last; ++p) maybe |= (x[p].y < a.y ? 1u : 0u) << (p - first);
        return maybe;
    }
    const double clearly_outside_squared = collider.radius * collider.radius * (1.0 + 1e-9);
#if defined(__SSE2__)
    const sse2::ParticlePair a_two = sse2::splat(a), n_two = sse2::splat(n);
    const __m128d outside = _mm_set1_pd(clearly_outside_squared);
    for (; p + 2 <= last; p += 2) {
        const sse2::ParticlePair d = sse2::load_pair(x, p) - a_two;  // m
        const __m128d sum = sse2::component_sums(plane ? d * n_two : d * d);
        // Plane: d < 0. Sphere: not (d² > r² (1 + 1e-9)), so a NaN counts as maybe inside.
        const __m128d inside =
            plane ? _mm_cmplt_pd(sum, _mm_setzero_pd()) : _mm_cmpngt_pd(sum, outside);
        maybe |= static_cast<unsigned>(_mm_movemask_pd(inside)) << (p - first);
    }
#endif
    for (; p < last; ++p) {
        const double dx = x[p].x - a.x, dy = x[p].y - a.y, dz = x[p].z - a.z;
        const bool inside = plane ? dx * n.x + dy * n.y + dz * n.z < 0.0
                                  : !(dx * dx + dy * dy + dz * dz > clearly_outside_squared);
        maybe |= (inside ? 1u : 0u) << (p - first);
    }
    return maybe;
}

// Work below this many particles stays on the calling thread (the hand-off costs more).
constexpr std::size_t min_particles_for_threads = 4096;

// Moves every free particle of [begin, end) found inside an impulse collider onto its
// surface, then hands it to `respond(collider, velocity, outward_normal)`; returns how many
// there were. Each particle meets the colliders in their order and nothing else, so
// particles are independent: any split of the range gives the same result.
template <class Respond>
std::size_t move_onto_impulse_colliders(std::span<const Collider> colliders, Vec3* positions,
                                        Vec3* velocities, const double* inverse_masses,
                                        std::size_t begin, std::size_t end, SweepWatch* watch,
                                        Respond respond) {
    // Most of the sheet, most of the time, is clear of the solid: the test runs over blocks
    // of particles without a branch (it vectorises), and only a block with a particle that
    // may be inside is looked at one particle at a time.
    constexpr std::size_t block = 32;
    std::size_t moved = 0;
    for (std::size_t first = begin; first < end; first += block) {
        const std::size_t last = std::min(first + block, end);
        for (const Collider& collider : colliders) {
            if (collider.response != ContactResponse::impulse) continue;
            const unsigned maybe = maybe_inside(collider, positions, first, last);
            if (maybe == 0) continue;
            const bool plane = collider.type == ColliderType::plane;
            for (std::size_t p = first; p < last; ++p) {
                if (!(maybe >> (p - first) & 1u) || inverse_masses[p] == 0.0) continue;  // pinned
                Vec3 n;
                const double distance = signed_distance(collider, positions[p], n);
                // A NaN distance: a sphere moves the particle (its test lets a NaN through),
                // a plane never has (its test does not).
                if (distance >= 0.0 || (plane && std::isnan(distance))) continue;
                ++moved;
                positions[p] -= distance * n;  // onto the surface
                respond(collider, velocities[p], n);
                if (watch) watch->check(p, positions[p], velocities[p]);
            }
        }
    }
    return moved;
}

// The same over the whole cloth, split between the pool's threads in blocks; the count is a
// sum of integers, the same for any split.
template <class Respond>
std::size_t move_onto_impulse_colliders(std::span<const Collider> colliders, Cloth& cloth,
                                        WorkerPool* pool, SweepWatch* watch, Respond respond) {
    const std::size_t count = cloth.particle_count();
    constexpr std::size_t block = 32;
    std::atomic<std::size_t> moved{0};
    parallel_for_if(pool, count >= min_particles_for_threads, (count + block - 1) / block,
                    [&](std::size_t first_block, std::size_t last_block) {
                        moved.fetch_add(
                            move_onto_impulse_colliders(
                                colliders, cloth.positions.data(), cloth.velocities.data(),
                                cloth.topology().inverse_masses.data(), first_block * block,
                                std::min(last_block * block, count), watch, respond),
                            std::memory_order_relaxed);
                    });
    return moved.load(std::memory_order_relaxed);
}

// Restitution along the normal, Coulomb friction across it, for a particle moved onto a
// collider's surface with velocity v.
void respond_with_impulse(const Collider& collider, Vec3& v, const Vec3& n) {
    const double normal_speed = glm::dot(v, n);
    if (normal_speed >= 0.0) return;  // already leaving
    const Vec3 tangential = v - normal_speed * n;
    const double normal_change = -(1.0 + collider.restitution) * normal_speed;
    const double sliding_speed = glm::length(tangential);
    const double tangential_scale =
        sliding_speed > 0.0 ? std::max(0.0, 1.0 - collider.friction * normal_change / sliding_speed)
                            : 0.0;
    v = -collider.restitution * normal_speed * n + tangential_scale * tangential;
}

}  // namespace

std::size_t resolve_impulse_contacts(std::span<const Collider> colliders, Cloth& cloth,
                                     WorkerPool* pool, SweepWatch* watch) {
    return move_onto_impulse_colliders(colliders, cloth, pool, watch, respond_with_impulse);
}

std::size_t resolve_impulse_contacts(std::span<const Collider> colliders, Vec3* positions,
                                     Vec3* velocities, const double* inverse_masses,
                                     std::size_t begin, std::size_t end, SweepWatch* watch) {
    return move_onto_impulse_colliders(colliders, positions, velocities, inverse_masses, begin, end,
                                       watch, respond_with_impulse);
}

std::size_t push_out_of_impulse_colliders(std::span<const Collider> colliders, Cloth& cloth,
                                          WorkerPool* pool, SweepWatch* watch) {
    // Only the velocity into the solid goes: restitution and friction were applied once, by
    // resolve_impulse_contacts.
    return move_onto_impulse_colliders(colliders, cloth, pool, watch,
                                       [](const Collider&, Vec3& v, const Vec3& n) {
                                           const double normal_speed = glm::dot(v, n);
                                           if (normal_speed < 0.0) v -= normal_speed * n;
                                       });
}

}  // namespace weft
