// libFuzzer target: the scene loader and --set parsing. Every input must either load or give
// an error that names where and what; none may crash, hang or allocate without bound. A
// scene that loads and is small enough is also built and stepped, so values the loader lets
// through cannot crash the simulation.
//
// Input layout: TOML text, then optionally a NUL byte and --set overrides, one per line.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "sim/core/simulation.h"
#include "sim/scene/obj_reader.h"
#include "sim/scene_io/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    const std::size_t split = input.find('\0');
    const std::string_view toml_text = input.substr(0, split);
    std::vector<std::string> overrides;
    if (split != std::string_view::npos) {
        std::string_view rest = input.substr(split + 1);
        while (!rest.empty()) {
            const std::size_t end = rest.find('\n');
            overrides.emplace_back(rest.substr(0, end));
            if (end == std::string_view::npos) break;
            rest.remove_prefix(end + 1);
        }
    }
    const weft::SceneLoadResult result = weft::load_scene_text(toml_text, "fuzz.toml", overrides);
    if (!result.ok()) {
        // A refusal must say where and what.
        if (!result.error || result.error->where.empty() || result.error->what.empty())
            std::abort();
        return 0;
    }
    const weft::Scene& scene = *result.scene;
    if (weft::Simulation::unsupported_feature(scene)) return 0;
    // Building is bounded by the loader's particle limit; stepping a big grid (or a big mesh
    // that a scene names on this machine) is only slow, so the fuzzer steps small ones, which
    // reach the same code within its timeout under ASan:
    // - implicit Euler solves a linear system each step and may split it into eight, so it
    //   steps a few times on a small sheet (a 64 x 64 sheet's twenty outlast the timeout);
    // - self-collision on a sheet crushed into a few points (a vertical sheet under the
    //   ground) tests every pair, so it steps a smaller sheet.
    const long long particles =
        scene.cloth.mesh_data.obj
            ? static_cast<long long>(scene.cloth.mesh_data.obj->vertices.size())
            : static_cast<long long>(scene.cloth.rows) * scene.cloth.cols;
    const bool implicit = scene.solver.integrator == weft::Integrator::implicit_euler;
    const long long particle_limit = implicit ? 256 : scene.self_collision_thickness ? 1024 : 4096;
    if (particles > particle_limit) return 0;
    const int steps = implicit ? 5 : 20;
    weft::Simulation simulation(scene);
    for (int step = 0; step < steps; ++step)
        if (simulation.step().diverged()) break;
    return 0;
}
