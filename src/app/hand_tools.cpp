#include "app/hand_tools.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <vector>

#include "sim/build/topology_edits.h"

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

ScreenPoints particles_on_screen(const Cloth& cloth, const raster::Camera& camera, int width,
                                 int height) {
    ScreenPoints on_screen(cloth.particle_count());
    for (std::size_t p = 0; p < cloth.particle_count(); ++p)
        if (auto w =
                raster::project_to_window(camera, width, height, glm::vec3(cloth.positions[p])))
            on_screen[p] = glm::vec2(w->x, w->y);
    return on_screen;
}

namespace {

using Point = glm::dvec2;  // in double: the products of float pixel coordinates are exact

double cross(const Point& u, const Point& v) {
    return u.x * v.y - u.y * v.x;
}

// The moments t in [0, 1] (with a little slack for rounding) where the quadratic
// a t² + b t + c is zero; none when it is zero throughout (the cursor slid along the
// spring's line, which crosses nothing).
std::vector<double> zeros_within_interval(double a, double b, double c) {
    constexpr double slack = 1e-9;
    std::vector<double> zeros;
    const double scale = std::max({std::abs(a), std::abs(b), std::abs(c)});
    if (scale == 0.0) return zeros;
    if (std::abs(a) <= 1e-12 * scale) {
        if (b != 0.0) zeros.push_back(-c / b);
    } else {
        const double discriminant = b * b - 4.0 * a * c;
        if (discriminant >= 0.0) {
            // The form that does not subtract nearly equal numbers.
            const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
            zeros.push_back(q / a);
            if (q != 0.0) zeros.push_back(c / q);
        }
    }
    std::erase_if(zeros, [](double t) { return !(t >= -slack && t <= 1.0 + slack); });
    return zeros;
}

}  // namespace

bool cursor_passes_spring(const glm::vec2& from, const glm::vec2& to, const ScreenSegment& before,
                          const ScreenSegment& now) {
    // Everything moves linearly in t from 0 (before) to 1 (now). With the spring's direction
    // d(t) = b - a and the cursor seen from its end a, e(t) = cursor - a, the cursor is on
    // the spring's line where f(t) = d × e = 0, a quadratic in t; it is on the spring itself
    // where, besides, its projection e·d / d·d lies in [0, 1].
    const Point d0 = Point(before.b) - Point(before.a), e0 = Point(from) - Point(before.a);
    const Point dd = Point(now.b) - Point(now.a) - d0, de = Point(to) - Point(now.a) - e0;
    const double a = cross(dd, de), b = cross(d0, de) + cross(dd, e0), c = cross(d0, e0);
    for (const double t : zeros_within_interval(a, b, c)) {
        const Point d = d0 + t * dd, e = e0 + t * de;
        const double length_squared = glm::dot(d, d);
        if (length_squared == 0.0) continue;  // coincident ends: no line to cross
        const double along = glm::dot(e, d) / length_squared;
        if (along >= -1e-9 && along <= 1.0 + 1e-9) return true;
    }
    return false;
}

std::vector<std::uint64_t> springs_along_stroke(const Cloth& cloth, const ScreenPoints& before,
                                                const ScreenPoints& now, const glm::vec2& from,
                                                const glm::vec2& to) {
    std::vector<std::uint64_t> crossed;
    for (const SpringGroup& group : cloth.topology().spring_groups)
        for (const Spring& spring : group.springs) {
            const auto &a0 = before[spring.i], &b0 = before[spring.j];
            const auto &a1 = now[spring.i], &b1 = now[spring.j];
            if (!a1 || !b1) continue;  // an end behind the camera: not on screen to cut
            // An end that came from behind the camera: judged where it is now.
            const ScreenSegment was = a0 && b0 ? ScreenSegment{*a0, *b0} : ScreenSegment{*a1, *b1};
            if (cursor_passes_spring(from, to, was, {*a1, *b1}))
                crossed.push_back(edge_key(spring.i, spring.j));
        }
    std::sort(crossed.begin(), crossed.end());
    return crossed;
}

std::vector<std::uint64_t> springs_along_stroke(const Cloth& cloth, const raster::Camera& camera,
                                                int width, int height, const glm::vec2& from,
                                                const glm::vec2& to) {
    const ScreenPoints on_screen = particles_on_screen(cloth, camera, width, height);
    return springs_along_stroke(cloth, on_screen, on_screen, from, to);
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
