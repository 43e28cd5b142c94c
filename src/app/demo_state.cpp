// Table of contents: construction · stepping with recovery · the hand · parameter changes ·
// scenes (reset, load, save).
#include "app/demo_state.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "app/hand_tools.h"
#include "sim/scene_loader.h"
#include "sim/scene_writer.h"

namespace weft::app {
namespace {

glm::vec3 to_vec3(const Vec3d& v) {
    return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

Vec3d to_vec3d(const glm::vec3& v) {
    return {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)};
}

CameraRig scene_rig(const Scene& scene) {
    return CameraRig::looking_at(to_vec3(scene.camera.position), to_vec3(scene.camera.target),
                                 static_cast<float>(scene.camera.fov_degrees));
}

}  // namespace

// ---- construction -------------------------------------------------------------------------

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

void DemoState::after_new_simulation() {
    cloth_view = view::ClothView(simulation.cloth());
    ground_height = view::ground_height_below(simulation.cloth(), simulation.colliders());
    hand = Hand{};
    last_good.reset();
    last_good_time = -1.0;
    clock.reset();
}

void DemoState::say(const std::string& text) {
    message = text;
    message_until = wall_now + 4.0;
    std::fprintf(stderr, "%s\n", text.c_str());
}

// ---- stepping with recovery -----------------------------------------------------------------

int DemoState::step(int steps) {
    for (int s = 0; s < steps; ++s) {
        const StepReport report = simulation.step();
        if (!report.diverged()) {
            // Keep a sound state from about a quarter second back.
            if (simulation.time() - last_good_time >= 0.25) {
                last_good = simulation;
                last_good_time = simulation.time();
            }
            continue;
        }
        // Roll back the motion, not the user's choices: the parameters stay as they are now,
        // only dt is halved. A drag in progress is let go (it may be what blew up).
        const Scene wanted = simulation.scene();
        const double diverged_at = simulation.time();
        const double halved_dt = 0.5 * simulation.dt();
        char text[512];
        if (halved_dt < smallest_recovery_dt) {
            simulation.reset();
            simulation.set_dt(scene.solver.dt);
            std::snprintf(text, sizeof text,
                          "diverged at t=%.3f s: %s — no step above %.0e s holds these "
                          "parameters; restarted the scene at dt %.3g ms",
                          diverged_at, report.divergence->c_str(), smallest_recovery_dt,
                          simulation.dt() * 1e3);
        } else {
            if (last_good) {
                simulation = *last_good;
                simulation.set_parameters(wanted);
            } else {
                simulation.reset();
            }
            simulation.set_dt(halved_dt);
            std::snprintf(text, sizeof text,
                          "diverged at t=%.3f s: %s — rolled back to t=%.3f s, dt halved to "
                          "%.3g ms",
                          diverged_at, report.divergence->c_str(), simulation.time(),
                          halved_dt * 1e3);
        }
        simulation.end_drag();
        hand.dragging = false;
        cloth_view = view::ClothView(simulation.cloth());
        ++recoveries;
        say(text);
        return s;
    }
    return steps;
}

// ---- the hand -----------------------------------------------------------------------------------

bool DemoState::grab(const glm::vec2& cursor, ViewSize view) {
    auto hit =
        cloth_under_cursor(simulation.cloth(), rig.camera(), view.width, view.height, cursor);
    if (!hit) return false;  // only grabs when the cursor is on the cloth
    simulation.start_drag(grab_cloth(simulation.cloth(), *hit, drag_radius));
    hand.dragging = simulation.drag().active();
    if (hand.dragging) hand.anchor = simulation.drag().target;
    return hand.dragging;
}

void DemoState::pull(const glm::vec2& cursor, ViewSize view) {
    if (!hand.dragging || !simulation.drag().active()) return;
    if (auto target =
            point_on_grab_plane(rig.camera(), view.width, view.height, cursor, hand.anchor))
        simulation.move_drag_target(*target);
}

void DemoState::let_go() {
    if (hand.dragging) simulation.end_drag();
    hand.dragging = false;
}

void DemoState::start_cut(const glm::vec2& cursor) {
    hand.cutting = true;
    hand.last_cursor = cursor;
}

std::size_t DemoState::cut_to(const glm::vec2& cursor, ViewSize view) {
    if (!hand.cutting) return 0;
    const std::size_t cut = cut_along_stroke(simulation, rig.camera(), view.width, view.height,
                                             hand.last_cursor, cursor);
    hand.last_cursor = cursor;
    return cut;
}

void DemoState::end_cut() {
    hand.cutting = false;
}

bool DemoState::toggle_pin(const glm::vec2& cursor, ViewSize view) {
    auto hit =
        cloth_under_cursor(simulation.cloth(), rig.camera(), view.width, view.height, cursor);
    if (!hit) return false;
    simulation.set_pinned(hit->particle, !simulation.cloth().is_pinned(hit->particle));
    return true;
}

// ---- parameter changes ------------------------------------------------------------------------

std::optional<std::string> DemoState::change(const std::vector<std::string>& edits) {
    // The running parameters as a scene file, with the edits as --set overrides: one set of
    // checks for files, the command line and the panel.
    return apply(load_scene_text(scene_to_toml(simulation.scene()), "panel", edits));
}

std::optional<std::string> DemoState::change_scene(const Scene& wanted) {
    return apply(load_scene_text(scene_to_toml(wanted), "panel"));
}

std::optional<std::string> DemoState::apply(const SceneLoadResult& checked) {
    if (!checked.ok()) return checked.error->message();
    if (Simulation::live_changeable(simulation.scene(), *checked.scene)) {
        simulation.set_parameters(*checked.scene);
        return std::nullopt;
    }
    // A new grid, placement, pins or collider shape: a new cloth.
    simulation = Simulation(*checked.scene);
    after_new_simulation();
    return std::nullopt;
}

void DemoState::move_collider(std::size_t index, const Vec3d& offset) {
    Scene wanted = simulation.scene();
    if (index >= wanted.colliders.size()) return;
    ColliderSpec& collider = wanted.colliders[index];
    for (int k = 0; k < 3; ++k) {
        collider.center[k] += offset[k];
        collider.point[k] += offset[k];
        if (!std::isfinite(collider.center[k]) || !std::isfinite(collider.point[k])) return;
    }
    // A finite move keeps every check of the loader satisfied: no need to go through it at
    // every frame of a held key.
    simulation.set_parameters(wanted);
    ground_height = view::ground_height_below(simulation.cloth(), simulation.colliders());
}

// ---- scenes -----------------------------------------------------------------------------------

void DemoState::reset_simulation() {
    simulation.reset();
    cloth_view = view::ClothView(simulation.cloth());
    hand = Hand{};
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
    rig = initial_rig = scene_rig(scene);
    after_new_simulation();
    return true;
}

Scene DemoState::scene_to_save() const {
    Scene saved = simulation.scene();
    saved.camera.position = to_vec3d(rig.position);
    saved.camera.target = to_vec3d(rig.position + rig.forward());
    saved.camera.fov_degrees = static_cast<double>(rig.fov_degrees);
    return saved;
}

bool DemoState::save_scene(const std::string& path, bool overwrite, std::string& error) const {
    namespace fs = std::filesystem;
    std::error_code exists_error;
    if (!overwrite && fs::exists(path, exists_error)) {
        error = path + ": exists; confirm to replace it";
        return false;
    }
    const std::string text = scene_to_toml(scene_to_save());
    // A unique temporary file in the same folder (rename is atomic only within one file
    // system), written and flushed to disk before it takes the final name.
    const fs::path folder = fs::path(path).parent_path();
    std::string temporary =
        (folder.empty() ? fs::path(".") : folder).string() + "/.weft-save-XXXXXX";
    const int fd = ::mkstemp(temporary.data());
    if (fd < 0) {
        error = path + ": cannot create a temporary file beside it: " + std::strerror(errno);
        return false;
    }
    bool written = true;
    for (std::size_t done = 0; written && done < text.size();) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        written = n > 0;
        if (written) done += static_cast<std::size_t>(n);
    }
    const int saved_errno = errno;
    written = written && ::fsync(fd) == 0;
    ::fchmod(fd, 0644);  // mkstemp makes it private; a scene file is an ordinary document
    ::close(fd);
    if (!written || ::rename(temporary.c_str(), path.c_str()) != 0) {
        error = path + ": cannot write: " + std::strerror(written ? errno : saved_errno);
        ::unlink(temporary.c_str());
        return false;
    }
    return true;
}

}  // namespace weft::app
