// libFuzzer target: the OBJ reader and the mesh builder. Every input must either read or be
// refused with a path, a line and a reason; none may crash, hang or allocate without bound.
// A mesh that reads and is small enough is also built into a cloth and stepped, so that
// meshes the reader lets through cannot crash the simulation.
//
// Input layout: the OBJ text.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string_view>

#include "sim/build/mesh_builder.h"
#include "sim/core/simulation.h"
#include "sim/scene/obj_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto mesh = std::make_shared<weft::ObjMesh>();
    try {
        *mesh = weft::read_obj_text(text, "fuzz.obj");
        weft::derive_mesh_topology(*mesh);
    } catch (const weft::ObjError& error) {
        // A refusal must say where and what; a line, when it is about the text.
        if (error.path() != "fuzz.obj" || error.line() < 1 || error.reason().empty()) std::abort();
        return 0;
    }
    // Building is bounded by the reader's limits; stepping a big mesh is only slow, so the
    // fuzzer steps small ones, with every spring family.
    if (mesh->vertices.size() > 4096) return 0;
    weft::Scene scene;
    scene.cloth.mesh = "fuzz.obj";
    scene.cloth.mesh_data.obj = mesh;
    scene.cloth.pin_preset = weft::PinPreset::vertices;
    scene.cloth.pin_vertices = {1};
    scene.shear.enabled = true;
    scene.bend.enabled = true;
    weft::Simulation simulation(scene);
    for (int step = 0; step < 20; ++step)
        if (simulation.step().diverged()) break;
    return 0;
}
