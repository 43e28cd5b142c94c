#include "sim/interaction/drag.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace weft {

void find_grip_springs(DragHandle& drag, const Cloth& cloth) {
    if (drag.grip_topology == cloth.topology().version && !drag.grip_springs.empty()) return;
    drag.grip_topology = cloth.topology().version;
    drag.grip_springs.clear();
    auto held = [&](std::uint32_t p) {
        return std::binary_search(drag.particles.begin(), drag.particles.end(), p);
    };
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        for (const Spring& spring : group.springs) {
            const bool i_held = held(spring.i), j_held = held(spring.j);
            if (i_held == j_held) continue;
            drag.grip_springs.push_back(
                i_held ? DragHandle::GripSpring{spring.i, spring.j, spring.rest_length}
                       : DragHandle::GripSpring{spring.j, spring.i, spring.rest_length});
        }
    }
}

DragHandle grab_cloth(const Cloth& cloth, const RayHit& hit, double radius) {
    DragHandle drag;
    drag.target = hit.point;
    drag.hand = hit.point;
    const double radius_squared = radius * radius;
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        if (cloth.is_pinned(p)) continue;
        const Vec3 offset = cloth.positions[p] - hit.point;
        const double distance_squared = glm::dot(offset, offset);
        double weight = 0.0;
        if (distance_squared < radius_squared) {
            const double falloff = 1.0 - distance_squared / radius_squared;
            weight = falloff * falloff;
        }
        if (p == hit.particle) weight = std::max(weight, 1.0);
        if (weight <= 0.0) continue;
        if (weight < 0.5) {
            drag.followers.push_back(static_cast<std::uint32_t>(p));
            drag.follower_weights.push_back(weight);
            continue;
        }
        drag.particles.push_back(static_cast<std::uint32_t>(p));
        drag.weights.push_back(weight);
        drag.offsets.push_back(offset);
    }
    find_grip_springs(drag, cloth);
    return drag;
}

void move_hand(DragHandle& drag, const Vec3& target, double time, double dt) {
    // A slow frame: a target that comes later than this is a hand that paused, not one that
    // moves slowly.
    constexpr double longest_interval = 1.0 / 30.0;  // s
    const double interval = std::clamp(time - drag.last_pull_time, dt, longest_interval);
    drag.target = target;
    drag.hand_speed = std::min(drag.max_hand_speed, glm::length(target - drag.hand) / interval);
    drag.last_pull_time = time;
}

void prescribe_hand_motion(DragHandle& drag, const Cloth& cloth, double dt) {
    // The hand's point: on towards the target, at most hand_speed × h.
    const Vec3 ahead = drag.target - drag.hand;
    const double distance = glm::length(ahead);
    const double reach = drag.hand_speed * dt;
    const Vec3 hand = distance <= reach ? drag.target : drag.hand + (reach / distance) * ahead;
    drag.hand_velocity = (hand - drag.hand) / dt;
    drag.hand = hand;
    drag.goals.resize(drag.particles.size());  // no-ops after the first step
    drag.velocities.resize(drag.particles.size());
    for (std::size_t k = 0; k < drag.particles.size(); ++k) {
        const Vec3 x = cloth.positions[drag.particles[k]];
        drag.goals[k] = drag.hand + drag.offsets[k];
        drag.velocities[k] = (drag.goals[k] - x) / dt;
    }
}

void start_hand_motion(const DragHandle& drag, Cloth& cloth, double dt) {
    // A particle pinned while in the hand stays where the pin holds it, at rest.
    for (std::size_t k = 0; k < drag.particles.size(); ++k)
        if (!cloth.is_pinned(drag.particles[k]))
            cloth.velocities[drag.particles[k]] = drag.velocities[k];
    // The fraction of the gap a follower closes in a step: (1 - w) left after each 1/60 s.
    constexpr double frame = 1.0 / 60.0;  // s
    for (std::size_t k = 0; k < drag.followers.size(); ++k) {
        Vec3& v = cloth.velocities[drag.followers[k]];
        const double closed = 1.0 - std::pow(1.0 - drag.follower_weights[k], dt / frame);
        v += closed * (drag.hand_velocity - v);
    }
}

void hold_in_hand(const DragHandle& drag, Cloth& cloth) {
    for (std::size_t k = 0; k < drag.particles.size(); ++k) {
        const std::uint32_t p = drag.particles[k];
        if (cloth.is_pinned(p)) continue;
        cloth.positions[p] = drag.goals[k];
        cloth.velocities[p] = drag.velocities[k];
    }
}

namespace {

// The grip springs' largest stretch with the held end at held(k) and the other at other(p).
template <class HeldEnd, class OtherEnd>
double largest_stretch(const DragHandle& drag, HeldEnd held, OtherEnd other) {
    double largest_squared = 1.0;
    for (const DragHandle::GripSpring& spring : drag.grip_springs) {
        const Vec3 d = other(spring.other) - held(spring.held);
        const double rest_squared = spring.rest_length * spring.rest_length;
        if (!(rest_squared > 0.0)) continue;
        largest_squared = std::max(largest_squared, glm::dot(d, d) / rest_squared);
    }
    return std::sqrt(largest_squared);
}

}  // namespace

double largest_grip_stretch(const DragHandle& drag, const Cloth& cloth) {
    const auto at = [&](std::uint32_t p) { return cloth.positions[p]; };
    return largest_stretch(drag, at, at);
}

double coming_grip_stretch(const DragHandle& drag, const Cloth& cloth, double dt) {
    const auto goal = [&](std::uint32_t p) {
        const auto k = std::lower_bound(drag.particles.begin(), drag.particles.end(), p) -
                       drag.particles.begin();
        return drag.goals[static_cast<std::size_t>(k)];
    };
    const auto coming = [&](std::uint32_t p) {
        return cloth.positions[p] + dt * cloth.velocities[p];
    };
    return largest_stretch(drag, goal, coming);
}

}  // namespace weft
