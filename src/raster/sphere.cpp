#include "raster/sphere.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/ext/matrix_transform.hpp>

namespace weft::raster {

TriangleMesh make_uv_sphere(int slices, int stacks) {
    slices = std::clamp(slices, 3, 1024);
    stacks = std::clamp(stacks, 2, 1024);
    TriangleMesh mesh;
    const auto ring = static_cast<std::uint32_t>(slices + 1);  // +1: the seam is duplicated
    for (int stack = 0; stack <= stacks; ++stack) {
        const float v = static_cast<float>(stack) / static_cast<float>(stacks);
        const float polar = v * std::numbers::pi_v<float>;
        for (int slice = 0; slice <= slices; ++slice) {
            const float u = static_cast<float>(slice) / static_cast<float>(slices);
            const float azimuth = u * 2.0f * std::numbers::pi_v<float>;
            const glm::vec3 p(std::sin(polar) * std::cos(azimuth), std::cos(polar),
                              -std::sin(polar) * std::sin(azimuth));
            mesh.positions.push_back(p);
            mesh.normals.push_back(p);
            mesh.uvs.emplace_back(u, v);
        }
    }
    for (int stack = 0; stack < stacks; ++stack) {
        for (int slice = 0; slice < slices; ++slice) {
            const auto top =
                static_cast<std::uint32_t>(stack) * ring + static_cast<std::uint32_t>(slice);
            const std::uint32_t bottom = top + ring;
            // Counter-clockwise from outside; the pole rows need only one triangle per cell.
            if (stack != 0) mesh.triangles.push_back({top, bottom, top + 1});
            if (stack != stacks - 1) mesh.triangles.push_back({top + 1, bottom, bottom + 1});
        }
    }
    return mesh;
}

MeshView sphere_view(const TriangleMesh& unit_sphere, const glm::vec3& centre, float radius) {
    const glm::mat4 model = glm::scale(glm::translate(glm::mat4(1.0f), centre), glm::vec3(radius));
    return unit_sphere.view(model);
}

bool draw_sphere(Framebuffer& framebuffer, const Camera& camera, const TriangleMesh& unit_sphere,
                 const glm::vec3& centre, float radius, const SurfaceStyle& style,
                 const Lighting& lighting, const PixelRect& scissor) {
    return draw_mesh(framebuffer, camera, sphere_view(unit_sphere, centre, radius), style, lighting,
                     scissor);
}

}  // namespace weft::raster
