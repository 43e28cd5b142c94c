// The plain float step most people write: plain_baseline.h's straightforward symplectic
// Euler — an array of particle structs, an array of spring structs each carrying its own
// material, one spring at a time, scalar code, a pinned flag tested in the loop — in single
// precision. The issue that asked for it (17) measured this float step at about half the
// time of the double one, so it, not the double baseline, is the fair "what a user writes"
// to hold weft's step against.
#pragma once

#include <vector>

#include "sim/cloth.h"
#include "sim/force_pass.h"

namespace weft::bench {

class PlainFloatCloth {
  public:
    PlainFloatCloth(const Cloth& cloth, const ForceField& field);
    void step_symplectic_euler(float dt);  // s
    // Same layout as Cloth::positions (double), for checking and measuring errors.
    std::vector<Vec3> positions() const;
    bool is_finite() const;

  private:
    struct Particle {
        float position[3];  // m
        float velocity[3];  // m/s
        float force[3];     // N
        float mass;         // kg
        bool pinned;
    };
    struct PlainSpring {
        int a, b;
        float stiffness, damping, rest_length;  // N/m, N·s/m, m
    };
    std::vector<Particle> particles_;
    std::vector<PlainSpring> springs_;
    float gravity_[3];  // m/s²
    float air_drag_;    // N·s/m per particle
    float wind_[3];     // m/s
};

}  // namespace weft::bench
