#include "sim/guards/stability_limit.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <vector>

namespace weft {
namespace {

// y = K x: the stiffness matrix applied to a displacement field, one spring at a time.
// A spring's block is B = k [u uᵀ + (1 - L/l)(I - u uᵀ)]; it adds B (x_i - x_j) to y_i and
// the opposite to y_j.
void apply_stiffness(const Cloth& cloth, const std::vector<Vec3>& x, std::vector<Vec3>& y) {
    std::fill(y.begin(), y.end(), Vec3(0.0));
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        for (const Spring& spring : group.springs) {
            const Vec3 d = cloth.positions[spring.j] - cloth.positions[spring.i];
            const double length = glm::length(d);
            if (length <= 0.0) continue;
            const Vec3 u = d / length;
            const Vec3 r = x[spring.i] - x[spring.j];
            const double along = glm::dot(u, r);
            const double tension_ratio = 1.0 - spring.rest_length / length;
            const Vec3 block_r = group.stiffness * (along * u + tension_ratio * (r - along * u));
            y[spring.i] += block_r;
            y[spring.j] -= block_r;
        }
    }
}

}  // namespace

double highest_angular_frequency(const Cloth& cloth, int max_iterations,
                                 double relative_tolerance) {
    const std::size_t count = cloth.particle_count();
    // Work in mass-weighted coordinates z = M^{1/2} x so the operator is symmetric; pinned
    // particles are held at zero (their rows and columns are removed).
    std::vector<double> inverse_sqrt_mass(count);
    for (std::size_t p = 0; p < count; ++p)
        inverse_sqrt_mass[p] =
            cloth.is_pinned(p) ? 0.0 : 1.0 / std::sqrt(cloth.topology().masses[p]);
    std::vector<Vec3> z(count), x(count), y(count);
    // A fixed, deterministic start with a component along every mode of a grid.
    for (std::size_t p = 0; p < count; ++p) {
        const auto phase = static_cast<double>(p);
        z[p] = Vec3(std::sin(1.0 + 0.731 * phase), std::cos(2.0 + 1.213 * phase),
                    std::sin(3.0 + 0.377 * phase)) *
               (inverse_sqrt_mass[p] > 0.0 ? 1.0 : 0.0);
    }
    std::vector<Vec3> unit(count);
    double estimate = 0.0;
    for (int iteration = 0; iteration < max_iterations; ++iteration) {
        double norm_squared = 0.0;
        for (const Vec3& v : z) norm_squared += glm::dot(v, v);
        if (norm_squared == 0.0) return 0.0;  // everything pinned, or no springs
        const double inverse_norm = 1.0 / std::sqrt(norm_squared);
        for (std::size_t p = 0; p < count; ++p) {
            unit[p] = z[p] * inverse_norm;
            x[p] = unit[p] * inverse_sqrt_mass[p];
        }
        apply_stiffness(cloth, x, y);
        // z <- M^{-1/2} K M^{-1/2} unit; its Rayleigh quotient unit · z estimates ω²_max.
        double rayleigh = 0.0;
        for (std::size_t p = 0; p < count; ++p) {
            z[p] = y[p] * inverse_sqrt_mass[p];
            rayleigh += glm::dot(unit[p], z[p]);
        }
        const bool converged =
            iteration > 10 && std::abs(rayleigh - estimate) <= relative_tolerance * rayleigh;
        estimate = rayleigh;
        if (converged) break;
    }
    return std::sqrt(std::max(estimate, 0.0));
}

double angular_frequency_bound(const Cloth& cloth) {
    std::vector<double> stiffness_sum(cloth.particle_count(), 0.0);
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        for (const Spring& spring : group.springs) {
            stiffness_sum[spring.i] += group.stiffness;
            stiffness_sum[spring.j] += group.stiffness;
        }
    }
    double bound = 0.0;
    for (std::size_t p = 0; p < cloth.particle_count(); ++p)
        if (!cloth.is_pinned(p))
            bound = std::max(bound, 2.0 * stiffness_sum[p] / cloth.topology().masses[p]);
    return std::sqrt(bound);
}

double damping_rate_bound(const Cloth& cloth, double air_drag) {
    std::vector<double> damping_sum(cloth.particle_count(), 0.0);
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        for (const Spring& spring : group.springs) {
            damping_sum[spring.i] += group.damping;
            damping_sum[spring.j] += group.damping;
        }
    }
    double bound = 0.0;
    for (std::size_t p = 0; p < cloth.particle_count(); ++p)
        if (!cloth.is_pinned(p))
            bound = std::max(bound, (2.0 * damping_sum[p] + air_drag) / cloth.topology().masses[p]);
    return bound;
}

double estimated_step_limit(const Cloth& cloth, double air_drag, Integrator integrator) {
    // Two methods need no bounds (each bound is a pass over the springs, and the panel asks
    // every frame).
    if (integrator == Integrator::implicit_euler) return std::numeric_limits<double>::infinity();
    if (integrator == Integrator::explicit_euler) return 0.0;
    const double omega = angular_frequency_bound(cloth);
    const double damping = damping_rate_bound(cloth, air_drag);
    const double symplectic_limit =
        4.0 / (damping + std::sqrt(damping * damping + 4.0 * omega * omega));
    // The symplectic methods' interval, or RK4's, √2 times as long.
    return integrator == Integrator::rk4 ? std::sqrt(2.0) * symplectic_limit : symplectic_limit;
}

double stable_step_limit(Integrator integrator, double omega_max) {
    if (omega_max <= 0.0) return std::numeric_limits<double>::infinity();
    switch (integrator) {
        case Integrator::symplectic_euler:
        case Integrator::verlet:
        case Integrator::velocity_verlet:
            return 2.0 / omega_max;
        case Integrator::rk4:
            return 2.0 * std::sqrt(2.0) / omega_max;
        case Integrator::explicit_euler:
            return 0.0;
        case Integrator::implicit_euler:
            return std::numeric_limits<double>::infinity();
    }
    return 0.0;
}

}  // namespace weft
