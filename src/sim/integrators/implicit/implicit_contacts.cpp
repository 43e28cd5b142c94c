#include "sim/integrators/implicit/implicit_contacts.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace weft {
namespace {

Vec3 read(const implicit_kernel::Field3& field, std::size_t i) {
    return {field.x[i], field.y[i], field.z[i]};
}

void write(const implicit_kernel::Field3& field, std::size_t i, const Vec3& value) {
    field.x[i] = static_cast<float>(value.x);
    field.y[i] = static_cast<float>(value.y);
    field.z[i] = static_cast<float>(value.z);
}

// The impulse (N·s) the surface gave a held particle, A v1 - b = A (v1 - v_k) - g, with
// job.applied = A (v1 - v_k) unfiltered.
double impulse_along_normal(const ContactConstraint& contact, const implicit_kernel::Job& job) {
    return glm::dot(contact.normal, read(job.applied, job.pad + contact.particle)) -
           contact.rhs_along_normal;
}

}  // namespace

void ImplicitContacts::choose(const Cloth& cloth, std::span<const Collider> solids,
                              const Vec3& gravity, double dt, std::span<const std::uint8_t> fixed,
                              implicit_kernel::Job& job) {
    for (const ContactConstraint& contact : held)
        write(job.contact_normal, job.pad + contact.particle, Vec3(0.0));
    held.clear();
    const std::size_t count = cloth.particle_count();
    for (std::size_t p = 0; p < count; ++p) {
        // A pin or the hand fixes the particle's velocity: that outranks a surface, and both
        // at once give its row no consistent solution (a hand pulling the cloth into the
        // floor gave non-finite positions).
        if (fixed[p] != 0) continue;
        const Vec3& x = cloth.positions[p];
        const Vec3& v = cloth.velocities[p];
        ContactConstraint best;
        bool found = false;
        double deepest = 0.0;  // m: the chosen surface's depth, past it (< 0)
        for (const Collider& solid : solids) {
            if (solid.response != ContactResponse::impulse) continue;
            Vec3 n;
            const double distance = signed_distance(solid, x, n);
            const double approach = glm::dot(v, n);
            const double ends_at = distance + dt * approach + dt * dt * glm::dot(gravity, n);
            const double depth = std::min(distance, ends_at);
            if (depth >= 0.0 || (found && depth >= deepest)) continue;
            found = true;
            deepest = depth;
            best.particle = static_cast<std::uint32_t>(p);
            best.normal = n;
            best.distance = distance;
            best.friction = solid.friction;
            // Onto the surface by the step's end; touching and approaching, a bounce.
            best.normal_speed = -distance / dt;
            if (distance <= 0.0)
                best.normal_speed = std::max(best.normal_speed, -solid.restitution * approach);
        }
        if (found) held.push_back(best);
    }
}

void ImplicitContacts::hold(implicit_kernel::Job& job) {
    job.has_contacts = !held.empty();
    for (ContactConstraint& contact : held) {
        const std::size_t i = job.pad + contact.particle;
        const Vec3& n = contact.normal;
        write(job.contact_normal, i, n);
        // g filtered: S g (the residual pass then forms S b); its normal part is what the
        // impulse is measured from.
        const Vec3 g = read(job.rhs_change, i);
        contact.rhs_along_normal = glm::dot(n, g);
        write(job.rhs_change, i, g - contact.rhs_along_normal * n);
        // The guess meets the constraint; every later change is filtered, so v1 does too.
        const Vec3 guess = read(job.solution, i);
        write(job.solution, i, guess + (contact.normal_speed - glm::dot(n, guess)) * n);
    }
}

std::size_t ImplicitContacts::let_go_of_pulled(implicit_kernel::Job& job) {
    const std::size_t before = held.size();
    std::erase_if(held, [&](const ContactConstraint& contact) {
        if (contact.distance < 0.0 || impulse_along_normal(contact, job) >= 0.0) return false;
        const std::size_t i = job.pad + contact.particle;
        write(job.contact_normal, i, Vec3(0.0));
        write(job.rhs_change, i,
              read(job.rhs_change, i) + contact.rhs_along_normal * contact.normal);
        return true;
    });
    job.has_contacts = !held.empty();
    return before - held.size();
}

void ImplicitContacts::apply_friction(const Cloth& cloth, implicit_kernel::Job& job) const {
    for (const ContactConstraint& contact : held) {
        const double impulse = impulse_along_normal(contact, job);  // N·s
        if (!(impulse > 0.0)) continue;
        const std::size_t i = job.pad + contact.particle;
        const Vec3& n = contact.normal;
        const Vec3 v = read(job.solution, i);
        const double normal_speed = glm::dot(n, v);
        const Vec3 sliding = v - normal_speed * n;
        const double sliding_speed = glm::length(sliding);
        if (sliding_speed <= 0.0) continue;
        const double stopped_by =
            contact.friction * impulse / cloth.topology().masses[contact.particle];  // m/s
        const double scale = std::max(0.0, 1.0 - stopped_by / sliding_speed);
        write(job.solution, i, normal_speed * n + scale * sliding);
    }
}

}  // namespace weft
