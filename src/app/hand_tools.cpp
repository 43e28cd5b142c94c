#include "app/hand_tools.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "sim/topology_edits.h"

namespace weft::app {

std::optional<RayHit> cloth_under_cursor(const Cloth& cloth, const raster::Camera& camera,
                                         int width, int height, const glm::vec2& window_point) {
    const raster::Ray ray = raster::camera_ray(camera, width, height, window_point);
    return cast_ray(cloth, Vec3(ray.origin), Vec3(ray.direction));
}

std::optional<Vec3> point_on_grab_plane(const raster::Camera& camera, int width, int height,
                                        const glm::vec2& window_point, const Vec3& anchor) {
    const raster::Ray ray = raster::camera_ray(camera, width, height, window_point);
    const Vec3 normal = Vec3(raster::camera_basis(camera).forward);
    const double facing = glm::dot(Vec3(ray.direction), normal);
    if (std::abs(facing) < 1e-9) return std::nullopt;
    const double distance = glm::dot(anchor - Vec3(ray.origin), normal) / facing;
    if (!(distance > 0.0)) return std::nullopt;
    return Vec3(ray.origin) + distance * Vec3(ray.direction);
}

bool segments_cross(const glm::vec2& a0, const glm::vec2& a1, const glm::vec2& b0,
                    const glm::vec2& b1) {
    auto side = [](const glm::vec2& p, const glm::vec2& q, const glm::vec2& r) {
        return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    };
    const float d1 = side(a0, a1, b0), d2 = side(a0, a1, b1), d3 = side(b0, b1, a0),
                d4 = side(b0, b1, a1);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 &&
           d4 != 0;
}

std::vector<std::uint64_t> springs_along_stroke(const Cloth& cloth, const raster::Camera& camera,
                                                int width, int height, const glm::vec2& from,
                                                const glm::vec2& to) {
    std::vector<std::optional<glm::vec2>> on_screen(cloth.particle_count());
    for (std::size_t p = 0; p < cloth.particle_count(); ++p)
        if (auto w =
                raster::project_to_window(camera, width, height, glm::vec3(cloth.positions[p])))
            on_screen[p] = glm::vec2(w->x, w->y);
    std::vector<std::uint64_t> crossed;
    for (const SpringGroup& group : cloth.spring_groups)
        for (const Spring& spring : group.springs) {
            const auto& a = on_screen[spring.i];
            const auto& b = on_screen[spring.j];
            if (a && b && segments_cross(*a, *b, from, to))
                crossed.push_back(edge_key(spring.i, spring.j));
        }
    std::sort(crossed.begin(), crossed.end());
    return crossed;
}

std::size_t cut_along_stroke(Simulation& simulation, const raster::Camera& camera, int width,
                             int height, const glm::vec2& from, const glm::vec2& to) {
    const std::vector<std::uint64_t> crossed =
        springs_along_stroke(simulation.cloth(), camera, width, height, from, to);
    if (crossed.empty()) return 0;
    return simulation.cut_springs([&](const Spring& s) {
        return std::binary_search(crossed.begin(), crossed.end(), edge_key(s.i, s.j));
    });
}

}  // namespace weft::app
