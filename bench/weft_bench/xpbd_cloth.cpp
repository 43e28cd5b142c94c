#include "xpbd_cloth.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace weft::bench {

XpbdCloth::XpbdCloth(const Cloth& cloth, const ForceField& field, bool spring_damping)
    : gravity_(field.gravity), wind_(field.wind) {
    const std::size_t count = cloth.particle_count();
    positions_.reserve(count);
    velocities_.reserve(count);
    for (std::size_t p = 0; p < count; ++p) {
        positions_.emplace_back(cloth.positions[p]);
        velocities_.emplace_back(cloth.velocities[p]);
        inverse_masses_.push_back(static_cast<float>(cloth.topology().inverse_masses[p]));
        drag_rates_.push_back(static_cast<float>(field.air_drag / cloth.topology().masses[p]));
    }
    previous_positions_ = positions_;
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        Family family{static_cast<float>(1.0 / group.stiffness),
                      spring_damping ? static_cast<float>(group.damping) : 0.0f,
                      {}};
        family.constraints.reserve(group.springs.size());
        for (const Spring& s : group.springs)
            family.constraints.push_back({s.i, s.j, static_cast<float>(s.rest_length)});
        families_.push_back(std::move(family));
    }
}

void XpbdCloth::step_frame(double frame_seconds, int substeps) {
    const auto h = static_cast<float>(frame_seconds / substeps);
    for (int s = 0; s < substeps; ++s) substep(h);
}

void XpbdCloth::cache_drag_factors(float h) {
    // One exp per particle when the substep changes, not one per particle per substep.
    if (h == drag_factors_h_) return;
    drag_factors_.resize(drag_rates_.size());
    for (std::size_t p = 0; p < drag_rates_.size(); ++p)
        drag_factors_[p] = std::exp(-h * drag_rates_[p]);
    drag_factors_h_ = h;
}

void XpbdCloth::substep(float h) {
    cache_drag_factors(h);
    const std::size_t count = positions_.size();
    glm::vec3* x = positions_.data();
    glm::vec3* p = previous_positions_.data();
    glm::vec3* v = velocities_.data();
    const float* w = inverse_masses_.data();
    const float* drag = drag_factors_.data();

    // Predict: gravity, then air drag as the exact decay of v - wind over h (the linear drag
    // force -a (v - wind) alone gives d(v - wind)/dt = -(a/m)(v - wind)), then move.
    for (std::size_t q = 0; q < count; ++q) {
        p[q] = x[q];
        if (w[q] == 0.0f) continue;  // pinned
        v[q] = wind_ + (v[q] + h * gravity_ - wind_) * drag[q];
        x[q] += h * v[q];
    }

    // Project: one Gauss–Seidel sweep over every spring, family by family, each correction
    // seen by the next. λ starts at 0 in each substep (one iteration: Δλ is all of λ).
    const float inverse_h = 1.0f / h;
    for (const Family& family : families_) {
        const float alpha_tilde = family.compliance * inverse_h * inverse_h;  // α / h², m/N/s²
        const float gamma = family.compliance * family.damping * inverse_h;   // α c / h
        for (const Constraint& c : family.constraints) {
            const float w_sum = w[c.i] + w[c.j];
            if (w_sum == 0.0f) continue;  // both ends pinned
            const glm::vec3 d = x[c.j] - x[c.i];
            const float length = glm::length(d);
            if (length == 0.0f) continue;  // coincident ends: no direction to push along
            const glm::vec3 u = d / length;
            // ∇C·(x - p): how far the ends moved apart along u in this substep, m.
            const float separation_rate = glm::dot(u, (x[c.j] - p[c.j]) - (x[c.i] - p[c.i]));
            const float delta_lambda = -(length - c.rest_length + gamma * separation_rate) /
                                       ((1.0f + gamma) * w_sum + alpha_tilde);
            x[c.i] -= (w[c.i] * delta_lambda) * u;
            x[c.j] += (w[c.j] * delta_lambda) * u;
        }
    }

    // The velocity the move implies; pinned particles stay at rest.
    for (std::size_t q = 0; q < count; ++q)
        if (w[q] != 0.0f) v[q] = (x[q] - p[q]) * inverse_h;
}

std::vector<Vec3> XpbdCloth::positions() const {
    return {positions_.begin(), positions_.end()};
}

std::vector<Vec3> XpbdCloth::velocities() const {
    return {velocities_.begin(), velocities_.end()};
}

Vec3 XpbdCloth::momentum() const {
    Vec3 total{0.0};
    for (std::size_t q = 0; q < velocities_.size(); ++q)
        if (inverse_masses_[q] != 0.0f) total += Vec3(velocities_[q]) / double(inverse_masses_[q]);
    return total;
}

bool XpbdCloth::is_finite() const {
    for (std::size_t q = 0; q < positions_.size(); ++q)
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(positions_[q][k]) || !std::isfinite(velocities_[q][k])) return false;
    return true;
}

}  // namespace weft::bench
