#include "plain_baseline.h"

#include <cmath>

namespace weft::bench {

template <class Real>
PlainClothOf<Real>::PlainClothOf(const Cloth& cloth, const ForceField& field) {
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        Particle particle{};
        for (int k = 0; k < 3; ++k) {
            particle.position[k] = static_cast<Real>(cloth.positions[p][k]);
            particle.velocity[k] = static_cast<Real>(cloth.velocities[p][k]);
        }
        particle.mass = static_cast<Real>(cloth.topology().masses[p]);
        particle.pinned = cloth.is_pinned(p);
        particles_.push_back(particle);
    }
    for (const SpringGroup& group : cloth.topology().spring_groups)
        for (const Spring& s : group.springs)
            springs_.push_back(
                {static_cast<int>(s.i), static_cast<int>(s.j), static_cast<Real>(group.stiffness),
                 static_cast<Real>(group.damping), static_cast<Real>(s.rest_length)});
    for (int k = 0; k < 3; ++k) {
        gravity_[k] = static_cast<Real>(field.gravity[k]);
        wind_[k] = static_cast<Real>(field.wind[k]);
    }
    air_drag_ = static_cast<Real>(field.air_drag);
}

template <class Real>
void PlainClothOf<Real>::step_symplectic_euler(Real dt) {
    // Gravity and air drag, f = m g - a (v - wind), then Hooke's law with the dashpot along
    // each spring, f_a = (k (|d| - L) + c (v_b - v_a)·u) u = -f_b; then v += dt f / m,
    // x += dt v (the new velocity: symplectic Euler).
    for (Particle& p : particles_)
        for (int k = 0; k < 3; ++k)
            p.force[k] = p.mass * gravity_[k] - air_drag_ * (p.velocity[k] - wind_[k]);
    for (const PlainSpring& s : springs_) {
        Particle& a = particles_[s.a];
        Particle& b = particles_[s.b];
        Real d[3], relative_velocity[3];
        for (int k = 0; k < 3; ++k) {
            d[k] = b.position[k] - a.position[k];
            relative_velocity[k] = b.velocity[k] - a.velocity[k];
        }
        const Real length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (length <= Real(0)) continue;  // coincident ends: no direction
        Real along = 0;
        for (int k = 0; k < 3; ++k) along += relative_velocity[k] * d[k] / length;
        const Real tension = s.stiffness * (length - s.rest_length) + s.damping * along;
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

template <class Real>
std::vector<Vec3> PlainClothOf<Real>::positions() const {
    std::vector<Vec3> result;
    result.reserve(particles_.size());
    for (const Particle& p : particles_)
        result.emplace_back(p.position[0], p.position[1], p.position[2]);
    return result;
}

template <class Real>
bool PlainClothOf<Real>::is_finite() const {
    for (const Particle& p : particles_)
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(p.position[k]) || !std::isfinite(p.velocity[k])) return false;
    return true;
}

template class PlainClothOf<double>;
template class PlainClothOf<float>;

}  // namespace weft::bench
