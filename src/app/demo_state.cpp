#include "app/demo_state.h"

#include "sim/scene_loader.h"

namespace weft::app {
namespace {

glm::vec3 to_vec3(const Vec3d& v) {
    return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

CameraRig scene_rig(const Scene& scene) {
    return CameraRig::looking_at(to_vec3(scene.camera.position), to_vec3(scene.camera.target),
                                 static_cast<float>(scene.camera.fov_degrees));
}

}  // namespace

DemoState::DemoState(const std::string& path, const std::vector<std::string>& scene_overrides,
                     const Scene& loaded)
    : scene_path(path),
      overrides(scene_overrides),
      scene(loaded),
      simulation(loaded),
      cloth_view(simulation.cloth()),
      ground_height(view::ground_height_below(simulation.cloth(), simulation.colliders())),
      rig(scene_rig(loaded)),
      initial_rig(rig) {}

void DemoState::reset_simulation() {
    simulation.reset();
    cloth_view = view::ClothView(simulation.cloth());
    last_good.reset();
    last_good_time = -1.0;
    clock.reset();
}

bool DemoState::load_scene(const std::string& path, std::string& error) {
    SceneLoadResult loaded = load_scene_file(path, overrides);
    if (!loaded.ok()) {
        error = loaded.error->message();
        return false;  // the running simulation is untouched
    }
    scene_path = path;
    scene = *loaded.scene;
    simulation = Simulation(scene);
    cloth_view = view::ClothView(simulation.cloth());
    ground_height = view::ground_height_below(simulation.cloth(), simulation.colliders());
    rig = initial_rig = scene_rig(scene);
    last_good.reset();
    last_good_time = -1.0;
    clock.reset();
    return true;
}

}  // namespace weft::app
