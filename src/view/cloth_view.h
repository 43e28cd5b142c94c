// ClothView: turns the cloth's current state into what the rasterizer draws — float
// positions, per-vertex normals, the triangles still intact (sim removes torn ones), texture
// coordinates for the pattern, and springs as lines coloured by strain. Used by the demo,
// the headless screenshot and the benchmarks, so they all show the same pixels.
#pragma once

#include <cstdint>
#include <vector>

#include "parallel/worker_pool.h"
#include "raster/colour.h"
#include "raster/grid_normals.h"
#include "raster/line_renderer.h"
#include "raster/mesh.h"
#include "raster/mesh_renderer.h"
#include "sim/core/cloth.h"

namespace weft::view {

class ClothView {
  public:
    explicit ClothView(const Cloth& cloth);

    // Copies positions, recomputes normals and, when springs were torn or cut since the last
    // call, the triangle and line lists. Allocates only when the topology changed. With a
    // pool, the vertices are split between its threads: the same values for any split.
    void update(const Cloth& cloth, WorkerPool* pool = nullptr);

    // The cloth as a mesh: positions, normals, intact triangles, uvs (metres along the cloth).
    raster::MeshView mesh() const;
    std::span<const glm::vec3> positions() const { return positions_; }
    std::span<const raster::TriangleIndices> triangles() const { return intact_triangles_; }
    // Every edge of the intact triangles once: the wireframe.
    std::span<const raster::LineIndices> wireframe_edges() const { return wireframe_edges_; }
    // One colour per particle: pinned ones highlighted.
    std::span<const raster::Rgba8> particle_colours(const Cloth& cloth);

    // Every live spring as a line, and its colour by strain (|d|/L - 1): neutral at rest,
    // warm when stretched, cool when compressed. Recomputed on each call.
    std::span<const raster::LineIndices> spring_lines() const { return spring_lines_; }
    std::span<const raster::Rgba8> spring_colours(const Cloth& cloth);
    // The springs the shaded surface does not show, with no intact triangle along them at an
    // end (lone_springs.h): what holds a piece that hangs by a thread after a cut or a tear.
    std::span<const raster::LineIndices> lone_springs() const { return lone_springs_; }

    // Scratch for the frame renderer: the mesh transformed for the current frame, its
    // triangles binned by band, and the spheres transformed, kept so that drawing allocates
    // nothing once the first frame is drawn.
    raster::PreparedMesh& prepared_mesh() { return prepared_mesh_; }
    raster::TriangleBands& triangle_bands() { return triangle_bands_; }
    std::vector<raster::PreparedMesh>& collider_meshes() { return collider_meshes_; }
    // The cloth as its shadow is drawn from: coarser where the grid is whole
    // (shadow_triangles.h).
    raster::MeshView shadow_caster() const;
    std::span<const std::uint32_t> shadow_vertices() const { return shadow_vertices_; }
    // The cloth's and the spheres' shadows on the floor (raster/planar_shadow.h).
    raster::PreparedMesh& shadow_mesh() { return shadow_mesh_; }
    raster::TriangleBands& shadow_bands() { return shadow_bands_; }
    std::vector<raster::PreparedMesh>& collider_shadows() { return collider_shadows_; }
    // The ground's and the plane colliders' grids, set up once a frame for every band.
    std::vector<raster::PreparedLine>& grid_lines() { return grid_lines_; }

  private:
    // Texture coordinates, m: a grid's from its rows and columns, a mesh's from its shape.
    void set_grid_uvs(const Cloth& cloth);
    void set_mesh_uvs(const Cloth& cloth);
    void rebuild_topology(const Cloth& cloth);

    std::vector<glm::vec3> positions_;
    std::vector<glm::vec3> normals_;
    std::vector<glm::vec2> uvs_;
    std::vector<raster::TriangleIndices> intact_triangles_;
    std::vector<raster::TriangleIndices> shadow_triangles_;  // shadow_triangles.h
    std::vector<std::uint32_t> shadow_vertices_;             // the particles they name
    raster::VertexTriangles triangles_around_;  // of intact_triangles_, for the normals
    std::vector<glm::vec3> face_normals_;       // one per intact triangle
    // While the triangles are the whole grid, the normals come from its rows instead.
    bool whole_grid_ = false;
    raster::GridNormals grid_normals_;
    std::vector<raster::LineIndices> wireframe_edges_;
    std::vector<raster::Rgba8> particle_colours_;
    std::vector<raster::LineIndices> spring_lines_;
    std::vector<raster::Rgba8> spring_line_colours_;
    std::vector<raster::LineIndices> lone_springs_;
    std::uint64_t topology_version_ = 0;  // of the topology the lines and triangles are from
    raster::PreparedMesh prepared_mesh_;
    raster::TriangleBands triangle_bands_;
    std::vector<raster::PreparedMesh> collider_meshes_;
    raster::PreparedMesh shadow_mesh_;
    raster::TriangleBands shadow_bands_;
    std::vector<raster::PreparedMesh> collider_shadows_;
    std::vector<raster::PreparedLine> grid_lines_;
};

}  // namespace weft::view
