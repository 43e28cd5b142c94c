#include "plain_float_baseline.h"

#include <cmath>

namespace weft::bench {

PlainFloatCloth::PlainFloatCloth(const Cloth& cloth, const ForceField& field) {
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        Particle particle{};
        for (int k = 0; k < 3; ++k) {
            particle.position[k] = static_cast<float>(cloth.positions[p][k]);
            particle.velocity[k] = static_cast<float>(cloth.velocities[p][k]);
        }
        particle.mass = static_cast<float>(cloth.masses[p]);
        particle.pinned = cloth.is_pinned(p);
        particles_.push_back(particle);
    }
    for (const SpringGroup& group : cloth.spring_groups)
        for (const Spring& s : group.springs)
            springs_.push_back(
                {static_cast<int>(s.i), static_cast<int>(s.j), static_cast<float>(group.stiffness),
                 static_cast<float>(group.damping), static_cast<float>(s.rest_length)});
    for (int k = 0; k < 3; ++k) {
        gravity_[k] = static_cast<float>(field.gravity[k]);
        wind_[k] = static_cast<float>(field.wind[k]);
    }
    air_drag_ = static_cast<float>(field.air_drag);
}

void PlainFloatCloth::step_symplectic_euler(float dt) {
    // Gravity and air drag, f = m g - a (v - wind), then Hooke's law with the dashpot along
    // each spring, f_a = (k (|d| - L) + c (v_b - v_a)·u) u = -f_b; then v += dt f / m,
    // x += dt v (the new velocity: symplectic Euler).
    for (Particle& p : particles_)
        for (int k = 0; k < 3; ++k)
            p.force[k] = p.mass * gravity_[k] - air_drag_ * (p.velocity[k] - wind_[k]);
    for (const PlainSpring& s : springs_) {
        Particle& a = particles_[s.a];
        Particle& b = particles_[s.b];
        float d[3], relative_velocity[3];
        for (int k = 0; k < 3; ++k) {
            d[k] = b.position[k] - a.position[k];
            relative_velocity[k] = b.velocity[k] - a.velocity[k];
        }
        const float length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (length <= 0.0f) continue;  // coincident ends: no direction
        float along = 0.0f;
        for (int k = 0; k < 3; ++k) along += relative_velocity[k] * d[k] / length;
        const float tension = s.stiffness * (length - s.rest_length) + s.damping * along;
        for (int k = 0; k < 3; ++k) {
            a.force[k] += tension * d[k] / length;
            b.force[k] -= tension * d[k] / length;
        }
    }
    for (Particle& p : particles_) {
        if (p.pinned) continue;
        for (int k = 0; k < 3; ++k) {
            p.velocity[k] += dt * p.force[k] / p.mass;
            p.position[k] += dt * p.velocity[k];
        }
    }
}

std::vector<Vec3> PlainFloatCloth::positions() const {
    std::vector<Vec3> result;
    result.reserve(particles_.size());
    for (const Particle& p : particles_)
        result.emplace_back(p.position[0], p.position[1], p.position[2]);
    return result;
}

bool PlainFloatCloth::is_finite() const {
    for (const Particle& p : particles_)
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(p.position[k]) || !std::isfinite(p.velocity[k])) return false;
    return true;
}

}  // namespace weft::bench
