#include "plain_baseline.h"

#include <cmath>

namespace weft::bench {

PlainCloth::PlainCloth(const Cloth& cloth, const ForceField& field) {
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        Particle particle{};
        for (int k = 0; k < 3; ++k) {
            particle.position[k] = cloth.positions[p][k];
            particle.velocity[k] = cloth.velocities[p][k];
        }
        particle.mass = cloth.masses[p];
        particle.pinned = cloth.is_pinned(p);
        particles_.push_back(particle);
    }
    for (const SpringGroup& group : cloth.spring_groups)
        for (const Spring& s : group.springs)
            springs_.push_back({static_cast<int>(s.i), static_cast<int>(s.j), group.stiffness, group.damping, s.rest_length});
    for (int k = 0; k < 3; ++k) gravity_[k] = field.gravity[k], wind_[k] = field.wind[k];
    air_drag_ = field.air_drag;
}

void PlainCloth::step_symplectic_euler(double dt) {
    for (Particle& p : particles_)
        for (int k = 0; k < 3; ++k) p.force[k] = p.mass * gravity_[k] - air_drag_ * (p.velocity[k] - wind_[k]);
    for (const PlainSpring& s : springs_) {
        Particle& a = particles_[s.a];
        Particle& b = particles_[s.b];
        double d[3], relative_velocity[3];
        for (int k = 0; k < 3; ++k) {
            d[k] = b.position[k] - a.position[k];
            relative_velocity[k] = b.velocity[k] - a.velocity[k];
        }
        const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (length <= 0.0) continue;
        double along = 0.0;
        for (int k = 0; k < 3; ++k) along += relative_velocity[k] * d[k] / length;
        const double tension = s.stiffness * (length - s.rest_length) + s.damping * along;
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

std::vector<Vec3> PlainCloth::positions() const {
    std::vector<Vec3> result;
    for (const Particle& p : particles_) result.emplace_back(p.position[0], p.position[1], p.position[2]);
    return result;
}

}  // namespace weft::bench
