#include "sim/guards/energy_guard.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>

#include "sim/core/energy.h"

namespace weft {
namespace {

// W: Σ air_drag (w · v), the wind's share of the air drag's power on the free particles.
double wind_power(const Cloth& cloth, const ForceField& field) {
    if (field.air_drag == 0.0 || field.wind == Vec3(0.0)) return 0.0;
    double power = 0.0;
    for (std::size_t p = 0; p < cloth.particle_count(); ++p)
        if (!cloth.is_pinned(p)) power += glm::dot(field.wind, cloth.velocities[p]);
    return field.air_drag * power;
}

double energy_scale(const Cloth& cloth, const ForceField& field) {
    double mass = 0.0;
    for (std::size_t p = 0; p < cloth.particle_count(); ++p)
        if (!cloth.is_pinned(p)) mass += cloth.topology().masses[p];
    const double diagonal =
        cloth.is_mesh()
            ? cloth.mesh_extent
            : cloth.spacing *
                  std::hypot(static_cast<double>(std::max(cloth.rows - 1, 0)) * cloth.row_pitch,
                             static_cast<double>(std::max(cloth.cols - 1, 0)));  // m
    return mass * (glm::length(field.gravity) * diagonal + 0.5);  // 0.5: ½ (1 m/s)²
}

}  // namespace

std::optional<std::string> EnergyGuard::check(const Cloth& cloth, const ForceField& field,
                                              double time, bool hand_pulls, WorkerPool* pool) {
    if (valid_ && time < next_check_) return std::nullopt;
    const double energy = measure_energy(cloth, field, pool).total();
    const double power = wind_power(cloth, field);
    if (!std::isfinite(energy)) return std::nullopt;  // the divergence guard's to report
    if (!valid_) {
        valid_ = true;
        work_ = 0.0;
        lowest_ = energy;
        lowest_time_ = time;
        scale_ = energy_scale(cloth, field);
    } else {
        work_ += 0.5 * (power + last_power_) * (time - last_time_);
    }
    last_time_ = time;
    last_power_ = power;
    next_check_ = time + check_interval;
    const double unsupplied = energy - work_;  // J
    if (hand_pulls || unsupplied < lowest_) {
        lowest_ = unsupplied;
        lowest_time_ = time;
        return std::nullopt;
    }
    const double gained = unsupplied - lowest_;
    if (!(gained > allowed_gain * scale_)) return std::nullopt;
    // Where it shows most: the fastest particle.
    std::size_t fastest = 0;
    double fastest_speed_squared = -1.0;
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        const double speed_squared = glm::dot(cloth.velocities[p], cloth.velocities[p]);
        if (speed_squared > fastest_speed_squared) {
            fastest_speed_squared = speed_squared;
            fastest = p;
        }
    }
    char message[320];
    std::snprintf(message, sizeof message,
                  "energy grew by %.3g J in %.3g s with nothing to supply it (the guard allows "
                  "%.3g J: half of the sheet's weight times its size); fastest: %s at %.3g m/s",
                  gained, time - lowest_time_, allowed_gain * scale_,
                  particle_name(cloth, fastest).c_str(), std::sqrt(fastest_speed_squared));
    return std::string(message);
}

}  // namespace weft
