// The scene key table (scene_keys.h) against the scene loader, which reads a file by its own
// code: every key the table names is a key the loader takes, by that dotted path, and the
// value the loader gives is what the table reads back from the loaded scene. A key whose
// name, kind or member in the table were wrong would fail here.
#include <gtest/gtest.h>

#include <string>

#include "sim/scene/scene_keys.h"
#include "sim/scene_io/scene_edit_toml.h"
#include "sim/scene_io/scene_loader.h"

namespace weft {
namespace {

// A value of `info`'s kind that differs from `current` where the rules allow, in TOML.
std::string other_value(const SceneKeyInfo& info, const SceneValue& current) {
    switch (info.kind) {
        case ValueKind::count:
            return "7";
        case ValueKind::number:
        case ValueKind::feature:
            return info.rule.minimum && *info.rule.minimum >= 1.0 ? "1.25" : "0.0625";
        case ValueKind::flag:  // structural springs cannot be switched off
            return std::get<bool>(current) && info.key != SceneKey::structural_enabled ? "false"
                                                                                       : "true";
        case ValueKind::vector:
            return "[0.5, -0.25, 2.0]";
        case ValueKind::choice:
            return "\"" + std::string(info.choices.back()) + "\"";
        case ValueKind::pins:
            return "[[0, 1], [2, 3]]";
    }
    return "";
}

TEST(SceneKeys, EveryKeyIsTheLoadersKeyForTheSameMember) {
    for (const SceneKeyInfo& info : scene_key_table()) {
        const bool collider = is_collider_key(info.key);
        const bool mesh_only = info.key == SceneKey::cloth_density;
        if (mesh_only) continue;  // needs an OBJ file; the mesh tests load it
        // --set reaches no [[colliders]] entry: a collider's key is given in the file.
        const std::string text = collider ? "[[colliders]]\ntype = \"plane\"\n" : "";
        const SceneValue defaults = info.get(load_scene_text(text, "keys.toml").scene.value(), 0);
        const std::string value = other_value(info, defaults);
        const std::string leaf(info.name.substr(info.name.find('.') + 1));
        const SceneLoadResult loaded =
            collider ? load_scene_text(text + leaf + " = " + value + "\n", "keys.toml")
                     : load_scene_text("", "keys.toml", {std::string(info.name) + "=" + value});
        ASSERT_TRUE(loaded.ok()) << info.name << " = " << value << ": " << loaded.error->message();
        const SceneValue read = info.get(*loaded.scene, 0);
        if (info.key != SceneKey::structural_enabled) {
            EXPECT_NE(read, defaults) << info.name << ": the override did not reach the member";
        }
        EXPECT_EQ(scene_value_toml(read), value) << info.name;
    }
}

TEST(SceneKeys, TheTableIsInTheEnumsOrderAndNamesEachKeyOnce) {
    const auto table = scene_key_table();
    ASSERT_EQ(table.size(), scene_key_count);
    for (std::size_t k = 0; k < table.size(); ++k) {
        EXPECT_EQ(static_cast<std::size_t>(table[k].key), k);
        for (std::size_t j = 0; j < k; ++j) EXPECT_NE(table[j].name, table[k].name);
    }
}

}  // namespace
}  // namespace weft
