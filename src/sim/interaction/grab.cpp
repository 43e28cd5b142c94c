#include "sim/interaction/grab.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace weft {

void find_grip_springs(Grab& grab, const Cloth& cloth) {
    if (grab.grip_topology == cloth.topology().version && !grab.grip_springs.empty()) return;
    grab.grip_topology = cloth.topology().version;
    grab.grip_springs.clear();
    auto held = [&](std::uint32_t p) {
        return std::binary_search(grab.particles.begin(), grab.particles.end(), p);
    };
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        for (const Spring& spring : group.springs) {
            const bool i_held = held(spring.i), j_held = held(spring.j);
            if (i_held == j_held) continue;
            grab.grip_springs.push_back(
                i_held ? Grab::GripSpring{spring.i, spring.j, spring.rest_length}
                       : Grab::GripSpring{spring.j, spring.i, spring.rest_length});
        }
    }
}

Grab grab_cloth(const Cloth& cloth, const RayHit& hit, double radius) {
    Grab grab;
    grab.target = hit.point;
    grab.hand = hit.point;
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
            grab.followers.push_back(static_cast<std::uint32_t>(p));
            grab.follower_weights.push_back(weight);
            continue;
        }
        grab.particles.push_back(static_cast<std::uint32_t>(p));
        grab.weights.push_back(weight);
        grab.offsets.push_back(offset);
    }
    find_grip_springs(grab, cloth);
    return grab;
}

void move_hand(Grab& grab, const Vec3& target, double time, double dt) {
    // A slow frame: a target that comes later than this is a hand that paused, not one that
    // moves slowly.
    constexpr double longest_interval = 1.0 / 30.0;  // s
    const double interval = std::clamp(time - grab.last_pull_time, dt, longest_interval);
    grab.target = target;
    grab.hand_speed = std::min(grab.max_hand_speed, glm::length(target - grab.hand) / interval);
    grab.last_pull_time = time;
}

void prescribe_hand_motion(Grab& grab, const Cloth& cloth, double dt) {
    // The hand's point: on towards the target, at most hand_speed × h.
    const Vec3 ahead = grab.target - grab.hand;
    const double distance = glm::length(ahead);
    const double reach = grab.hand_speed * dt;
    const Vec3 hand = distance <= reach ? grab.target : grab.hand + (reach / distance) * ahead;
    grab.hand_velocity = (hand - grab.hand) / dt;
    grab.hand = hand;
    grab.goals.resize(grab.particles.size());  // no-ops after the first step
    grab.velocities.resize(grab.particles.size());
    for (std::size_t k = 0; k < grab.particles.size(); ++k) {
        const Vec3 x = cloth.positions[grab.particles[k]];
        grab.goals[k] = grab.hand + grab.offsets[k];
        grab.velocities[k] = (grab.goals[k] - x) / dt;
    }
}

void start_hand_motion(const Grab& grab, Cloth& cloth, double dt) {
    // A particle pinned while in the hand stays where the pin holds it, at rest.
    for (std::size_t k = 0; k < grab.particles.size(); ++k)
        if (!cloth.is_pinned(grab.particles[k]))
            cloth.velocities[grab.particles[k]] = grab.velocities[k];
    // The fraction of the gap a follower closes in a step: (1 - w) left after each 1/60 s.
    constexpr double frame = 1.0 / 60.0;  // s
    for (std::size_t k = 0; k < grab.followers.size(); ++k) {
        Vec3& v = cloth.velocities[grab.followers[k]];
        const double closed = 1.0 - std::pow(1.0 - grab.follower_weights[k], dt / frame);
        v += closed * (grab.hand_velocity - v);
    }
}

void hold_in_hand(const Grab& grab, Cloth& cloth) {
    for (std::size_t k = 0; k < grab.particles.size(); ++k) {
        const std::uint32_t p = grab.particles[k];
        if (cloth.is_pinned(p)) continue;
        cloth.positions[p] = grab.goals[k];
        cloth.velocities[p] = grab.velocities[k];
    }
}

double largest_grip_stretch(const Grab& grab, const Cloth& cloth) {
    return largest_grip_stretch(grab.grip_springs, cloth.positions);
}

double coming_grip_stretch(const Grab& grab, const Cloth& cloth, double dt) {
    const auto goal = [&](std::uint32_t p) {
        const auto k = std::lower_bound(grab.particles.begin(), grab.particles.end(), p) -
                       grab.particles.begin();
        return grab.goals[static_cast<std::size_t>(k)];
    };
    const auto coming = [&](std::uint32_t p) {
        return cloth.positions[p] + dt * cloth.velocities[p];
    };
    return largest_grip_stretch(grab.grip_springs, goal, coming);
}

}  // namespace weft
