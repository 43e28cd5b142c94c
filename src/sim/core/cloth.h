// Cloth: the general topology of a mass-spring cloth (particles, springs grouped by family,
// triangles) as flat arrays, plus its per-step state (positions, velocities).
//
// Layout follows the loops that read it (Box2D v3 / Jolt style): the force pass walks one
// spring group at a time over `{i, j, rest_length}` records and reads positions and
// velocities by index; integrators walk the particle arrays linearly. Nothing here points
// at anything else: springs and triangles refer to particles by index.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/grid/grid_stencil.h"

namespace weft {

using Vec3 = glm::dvec3;

enum class SpringFamily : std::uint8_t { structural, shear, bend };

const char* spring_family_name(SpringFamily family);

struct Cloth;
// How messages name particle p: "particle (row R, col C)" on a grid, "vertex N" on a mesh,
// N counted from 1 as the OBJ file counts it.
std::string particle_name(const Cloth& cloth, std::size_t p);

struct Spring {
    std::uint32_t i;     // first particle
    std::uint32_t j;     // second particle
    double rest_length;  // m, length at which the spring exerts no elastic force
};

// All springs of one family share a material; a family the scene does not ask for has no
// group at all, so it costs nothing in the force pass.
struct SpringGroup {
    SpringFamily family = SpringFamily::structural;
    double stiffness = 0.0;       // N/m
    double damping = 0.0;         // N·s/m, acts on the relative velocity along the spring
    std::vector<Spring> springs;  // sorted by colour (spring_coloring.h)
    // springs[colour_starts[k] .. colour_starts[k+1]) is colour k: no two of its springs share
    // a particle. The last entry is where springs that fit no colour start; those are applied
    // one by one. Empty: not coloured, everything is applied one by one.
    std::vector<std::uint32_t> colour_starts;
};

struct Triangle {
    std::uint32_t a, b, c;  // particle indices, counter-clockwise seen from the front side
};

// What a cloth is made of, as opposed to where it is: particles' masses and pins, springs
// grouped by family, triangles, and the grid stencil where there is one. Shared, immutable,
// between every copy of a cloth (recovery snapshots, rollbacks, runs side by side): a copy
// costs its state only. Whatever changes it (a tear, a cut, a pin, a new material) goes
// through Cloth::edit_topology, which copies it first if another cloth still holds it, and
// gives it a new version.
struct ClothTopology {
    // Per-particle constants.
    std::vector<double> masses;          // kg
    std::vector<double> inverse_masses;  // 1/kg; 0 for a pinned particle, which never moves
    std::vector<std::uint32_t> pinned;   // indices of pinned particles, ascending

    std::vector<SpringGroup> spring_groups;  // only the families present
    std::vector<Triangle> triangles;         // for drawing; two per grid cell
    // The same springs as per-direction grid stencils, for the structured force pass; empty
    // for a cloth that is not a plain grid (grid_stencil.h).
    GridStencil grid_stencil;

    // Different for every edit of any topology, in any cloth: what views and caches compare
    // to notice a change (a torn spring, a pin), instead of counting.
    std::uint64_t version = 0;

    std::size_t spring_count() const;
    const SpringGroup* find_group(SpringFamily family) const;
};

struct Cloth {
    int rows = 0;  // grid rows the cloth was built from (particle = row * cols + col)
    int cols = 0;
    double spacing = 0.0;        // m, rest distance between grid neighbours
    double row_pitch = 1.0;      // rest distance between rows, in spacings (offset: √3/2)
    double odd_row_shift = 0.0;  // odd rows' shift along a row, in spacings (offset: 1/2)
    // A mesh cloth (mesh_builder.h) is no grid: its particles count as one row (rows = 1,
    // cols = particle count), `spacing` is its mean structural rest length, and this is its
    // size, the diagonal of its rest shape's bounding box, m. 0 for the grid builders' cloths,
    // whose size follows from rows, cols and spacing.
    double mesh_extent = 0.0;
    // A mesh cloth's vertices as built (origin applied), m: its rest shape, which a view lays
    // its texture on. Shared by copies (snapshots, companions); null for the grid builders'.
    std::shared_ptr<const std::vector<Vec3>> mesh_rest_shape;

    // Per-step state.
    std::vector<Vec3> positions;   // m
    std::vector<Vec3> velocities;  // m/s

    // The topology, shared with every copy of this cloth until one of them edits it.
    const ClothTopology& topology() const { return *topology_; }
    // The topology to change: this cloth's own (copied first if shared), with a new version.
    ClothTopology& edit_topology();
    // How many cloths hold this topology (1: only this one), for tests and measurements.
    long topology_holders() const { return topology_.use_count(); }

    std::size_t particle_count() const { return positions.size(); }
    bool is_mesh() const { return mesh_extent > 0.0; }  // built from a mesh (mesh_builder.h)
    // m: the rest shape's longest side: a grid's longer edge, a mesh's bounding-box diagonal.
    // How far the cloth can reach from a point it hangs by, give or take.
    double rest_span() const { return is_mesh() ? mesh_extent : std::max(rows, cols) * spacing; }
    std::size_t spring_count() const { return topology_->spring_count(); }
    bool is_pinned(std::size_t particle) const {
        return topology_->inverse_masses[particle] == 0.0;
    }
    const SpringGroup* find_group(SpringFamily family) const {
        return topology_->find_group(family);
    }

  private:
    std::shared_ptr<ClothTopology> topology_ = std::make_shared<ClothTopology>();
};

}  // namespace weft
