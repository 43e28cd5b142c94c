// The plain baseline weft's speed is measured against: the same force model and symplectic
// Euler step written the straightforward way — an array of particle structs, an array of
// spring structs each carrying its own material, one spring at a time, scalar code, a
// pinned flag tested in the loop. Built with the same flags and timed in the same process,
// so the speed-up is a ratio that holds on a noisy machine.
#pragma once

#include <vector>

#include "sim/cloth.h"
#include "sim/force_pass.h"

namespace weft::bench {

class PlainCloth {
public:
    PlainCloth(const Cloth& cloth, const ForceField& field);
    void step_symplectic_euler(double dt);
    // Same layout as Cloth::positions, for checking that both agree.
    std::vector<Vec3> positions() const;

private:
    struct Particle {
        double position[3];
        double velocity[3];
        double force[3];
        double mass;
        bool pinned;
    };
    struct PlainSpring {
        int a, b;
        double stiffness, damping, rest_length;
    };
    std::vector<Particle> particles_;
    std::vector<PlainSpring> springs_;
    double gravity_[3];
    double air_drag_;
    double wind_[3];
};

}  // namespace weft::bench
