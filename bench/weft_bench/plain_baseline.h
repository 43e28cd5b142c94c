// The plain step weft's speed is measured against: the same force model and symplectic Euler
// step written the straightforward way — an array of particle structs, an array of spring
// structs each carrying its own material, one spring at a time, scalar code, a pinned flag
// tested in the loop. Built with the same flags and timed in the same process, so the
// speed-up is a ratio that holds on a noisy machine.
//
// In double (PlainCloth, the throughput study's baseline) and in float (PlainFloatCloth):
// the float step is what most people write, and it was measured at about half the double one's
// time, so it, not the double baseline, is the fair "what a user writes" to hold weft's step
// against (the realtime study does).
#pragma once

#include <vector>

#include "sim/core/cloth.h"
#include "sim/core/force_pass.h"

namespace weft::bench {

template <class Real>
class PlainClothOf {
  public:
    PlainClothOf(const Cloth& cloth, const ForceField& field);
    void step_symplectic_euler(Real dt);  // s
    // Same layout as Cloth::positions (double), for checking and measuring errors.
    std::vector<Vec3> positions() const;
    bool is_finite() const;

  private:
    struct Particle {
        Real position[3];  // m
        Real velocity[3];  // m/s
        Real force[3];     // N
        Real mass;         // kg
        bool pinned;
    };
    struct PlainSpring {
        int a, b;
        Real stiffness, damping, rest_length;  // N/m, N·s/m, m
    };
    std::vector<Particle> particles_;
    std::vector<PlainSpring> springs_;
    Real gravity_[3];  // m/s²
    Real air_drag_;    // N·s/m per particle
    Real wind_[3];     // m/s
};

using PlainCloth = PlainClothOf<double>;
using PlainFloatCloth = PlainClothOf<float>;

}  // namespace weft::bench
