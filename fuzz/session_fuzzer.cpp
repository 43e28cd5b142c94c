// libFuzzer target: session recordings (weft --replay FILE). Every input must either read or
// give an error that names where and what; none may crash, hang or allocate without bound.
// A recording that reads and is small (a few thousand steps of a small cloth) is also
// replayed through the demo's own stepping, so events the reader lets through (a grab of a
// particle that does not exist, a cut of springs that are not there, parameters that blow
// the cloth up) cannot crash the replay.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <variant>

#include "app/demo_state.h"
#include "app/session_record.h"
#include "sim/scene_io/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    std::string error;
    const auto record = weft::app::session_from_toml(text, "fuzz.toml", error);
    if (!record) {
        if (error.empty()) std::abort();  // a refusal must say where and what
        return 0;
    }
    const weft::SceneLoadResult scene = weft::load_scene_text(record->scene_toml, "scene");
    if (!scene.ok()) std::abort();  // the reader checked it
    // Implicit Euler solves a linear system each step and may split a step into eight, so a
    // recording that uses it is replayed only on a small sheet for a few steps: the same code,
    // within the fuzzer's timeout under ASan.
    bool implicit = scene.scene->solver.integrator == weft::Integrator::implicit_euler;
    long long particles = static_cast<long long>(scene.scene->cloth.rows) * scene.scene->cloth.cols;
    std::int64_t largest_edited_side = 0;
    for (const auto& timed : record->events) {
        if (timed.event.kind == weft::app::ClothEvent::Kind::parameters) {
            if (!timed.event.scene) std::abort();  // the reader checked it
            const weft::Scene& next = *timed.event.scene;
            particles =
                std::max(particles, static_cast<long long>(next.cloth.rows) * next.cloth.cols);
            implicit = implicit || next.solver.integrator == weft::Integrator::implicit_euler;
        }
        for (const weft::SceneEdit& edit : timed.event.edits) {
            if (edit.key == weft::SceneKey::cloth_rows || edit.key == weft::SceneKey::cloth_cols)
                largest_edited_side =
                    std::max(largest_edited_side, std::get<std::int64_t>(edit.value));
            if (edit.key == weft::SceneKey::integrator) implicit = true;
        }
    }
    // Beyond these it is only slow, not wrong.
    if (implicit ? particles > 256 || largest_edited_side > 16 || record->steps > 200
                 : particles > 1024 || largest_edited_side > 32 || record->steps > 4000)
        return 0;
    weft::app::DemoState state("fuzz.toml", {}, *scene.scene);
    state.start_replay(*record);
    while (!state.replay_finished()) state.step(512);
    (void)state.replay_matches();
    return 0;
}
