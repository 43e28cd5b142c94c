#include "view/cloth_view.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "raster/strain_colour.h"
#include "view/lone_springs.h"
#include "view/shadow_triangles.h"

namespace weft::view {

ClothView::ClothView(const Cloth& cloth) {
    const std::size_t count = cloth.particle_count();
    positions_.resize(count);
    normals_.resize(count);
    uvs_.resize(count);
    // Texture coordinates: where the particle sits in the flat rest sheet, in metres, so a
    // pattern keeps its size whatever the resolution or layout.
    if (cloth.mesh_rest_shape && cloth.mesh_rest_shape->size() == count) {
        set_mesh_uvs(cloth);
    } else {
        set_grid_uvs(cloth);
    }
    rebuild_topology(cloth);
    update(cloth);
}

void ClothView::set_grid_uvs(const Cloth& cloth) {
    for (std::size_t p = 0; p < uvs_.size(); ++p) {
        const auto row = static_cast<double>(p / cloth.cols),
                   col = static_cast<double>(p % cloth.cols);
        const double shift = (p / cloth.cols) % 2 ? cloth.odd_row_shift : 0.0;
        uvs_[p] = glm::vec2(static_cast<float>((col + shift) * cloth.spacing),
                            static_cast<float>(row * cloth.row_pitch * cloth.spacing));
    }
}

void ClothView::set_mesh_uvs(const Cloth& cloth) {
    // A mesh has no rows; its texture lies on its shape as built, at rest. Along the axis
    // its box is thinnest: a flat mesh (thinner than a quarter of its next side) is projected
    // onto its plane; any other (a skirt, a tube) is unrolled around that axis, the angle
    // times the mean distance from the axis against the height (one seam, where the angle
    // wraps). In metres either way.
    const std::vector<Vec3>& rest = *cloth.mesh_rest_shape;  // m
    Vec3 low = rest.empty() ? Vec3(0.0) : rest.front(), high = low;
    for (const Vec3& x : rest) {
        low = glm::min(low, x);
        high = glm::max(high, x);
    }
    const Vec3 size = high - low, centre = 0.5 * (low + high);  // m
    int axis = 0;
    for (int a = 1; a < 3; ++a)
        if (size[a] < size[axis]) axis = a;
    const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
    const bool flat = size[axis] < 0.25 * std::min(size[u], size[v]);
    double mean_radius = 0.0;  // m
    for (const Vec3& x : rest) mean_radius += std::hypot(x[u] - centre[u], x[v] - centre[v]);
    mean_radius /= static_cast<double>(std::max<std::size_t>(rest.size(), 1));
    for (std::size_t p = 0; p < uvs_.size(); ++p) {
        const Vec3& x = rest[p];
        if (flat) {
            uvs_[p] =
                glm::vec2(static_cast<float>(x[u] - low[u]), static_cast<float>(x[v] - low[v]));
        } else {
            const double angle = std::atan2(x[v] - centre[v], x[u] - centre[u]);  // rad
            uvs_[p] = glm::vec2(static_cast<float>(angle * mean_radius),
                                static_cast<float>(x[axis] - low[axis]));
        }
    }
}

void ClothView::rebuild_topology(const Cloth& cloth) {
    topology_version_ = cloth.topology().version;
    spring_lines_.clear();
    for (const SpringGroup& group : cloth.topology().spring_groups)
        for (const Spring& spring : group.springs) spring_lines_.push_back({spring.i, spring.j});
    intact_triangles_.clear();
    for (const Triangle& t : cloth.topology().triangles)
        intact_triangles_.push_back({t.a, t.b, t.c});
    find_shadow_triangles(cloth, intact_triangles_, shadow_block_cells(cloth), shadow_triangles_,
                          shadow_vertices_);
    wireframe_edges_ = raster::unique_edges(intact_triangles_);
    raster::find_vertex_triangles(intact_triangles_, positions_.size(), triangles_around_);
    whole_grid_ = !cloth.mesh_rest_shape &&
                  static_cast<std::size_t>(cloth.rows) * static_cast<std::size_t>(cloth.cols) ==
                      positions_.size() &&
                  raster::is_whole_grid(intact_triangles_, cloth.rows, cloth.cols);
    if (whole_grid_) grid_normals_.resize(cloth.rows, cloth.cols);
    face_normals_.resize(whole_grid_ ? 0 : intact_triangles_.size());
    lone_springs_ = find_lone_springs(cloth, uvs_, intact_triangles_, triangles_around_);
}

void ClothView::update(const Cloth& cloth, WorkerPool* pool) {
    // A tear, a cut, a pin or a new material gives the topology a new version.
    if (cloth.topology().version != topology_version_) rebuild_topology(cloth);
    // Positions, then every face normal, then each vertex's sum of its faces: each pass
    // reads what the one before wrote, and within a pass every element is independent.
    auto copy_positions = [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) positions_[p] = glm::vec3(cloth.positions[p]);
        if (whole_grid_) grid_normals_.load_positions(positions_, begin, end);
    };
    auto find_faces = [&](std::size_t begin, std::size_t end) {
        raster::compute_face_normals(positions_, intact_triangles_, face_normals_, begin, end);
    };
    auto gather_normals = [&](std::size_t begin, std::size_t end) {
        raster::gather_vertex_normals(face_normals_, triangles_around_, normals_, begin, end);
    };
    // The whole grid's passes go by rows: cell rows for the faces, vertex rows for the sums.
    auto find_grid_faces = [&](std::size_t begin, std::size_t end) {
        grid_normals_.find_faces(begin, end);
    };
    auto gather_grid_normals = [&](std::size_t begin, std::size_t end) {
        grid_normals_.gather(normals_, begin, end);
    };
    const std::size_t count = positions_.size();
    constexpr std::size_t min_vertices_for_threads = 4096;
    const bool worth_threads = count >= min_vertices_for_threads;
    auto run = [&](std::size_t items, auto&& pass) {
        parallel_for_if(pool, worth_threads, items, pass);
    };
    run(count, copy_positions);
    if (whole_grid_) {
        const auto rows = static_cast<std::size_t>(grid_normals_.rows());
        run(rows - 1, find_grid_faces);
        run(rows, gather_grid_normals);
    } else {
        run(intact_triangles_.size(), find_faces);
        run(count, gather_normals);
    }
}

std::span<const raster::Rgba8> ClothView::particle_colours(const Cloth& cloth) {
    particle_colours_.assign(cloth.particle_count(), raster::Rgba8{230, 230, 230, 255});
    for (std::uint32_t p : cloth.topology().pinned)
        particle_colours_[p] = raster::Rgba8{255, 210, 40, 255};
    return particle_colours_;
}

raster::MeshView ClothView::mesh() const {
    return {positions_,
            normals_,
            intact_triangles_,
            uvs_,
            {},
            glm::mat4(1.0f),
            whole_grid_ ? grid_normals_.cols() : 0};
}

raster::MeshView ClothView::shadow_caster() const {
    return {positions_, normals_, shadow_triangles_, {}, {}, glm::mat4(1.0f)};
}

std::span<const raster::Rgba8> ClothView::spring_colours(const Cloth& cloth) {
    spring_line_colours_.resize(spring_lines_.size());
    std::size_t line = 0;
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        for (const Spring& spring : group.springs) {
            const double length =
                glm::length(cloth.positions[spring.j] - cloth.positions[spring.i]);
            const auto strain = static_cast<float>(length / spring.rest_length - 1.0);
            spring_line_colours_[line++] = raster::to_rgba8(raster::colour_for_strain(strain));
        }
    }
    return spring_line_colours_;
}

}  // namespace weft::view
