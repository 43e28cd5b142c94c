// weft: entry point. Parses the command line and hands over to the runner it asks for.
#include <cstdio>
#include <string>
#include <variant>
#include <vector>

#include "app/command_line.h"
#include "app/demo_window.h"
#include "app/headless_runner.h"
#include "app/scene_folder.h"

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    auto parsed = weft::parse_command_line(args);
    if (auto* error = std::get_if<weft::CommandLineError>(&parsed)) {
        std::fprintf(stderr, "error: %s: %s\n", error->where.c_str(), error->what.c_str());
        std::fprintf(stderr, "%s", weft::usage_text());
        return weft::exit_bad_input;
    }
    const auto& command_line = std::get<weft::CommandLine>(parsed);
    if (command_line.help) {
        std::printf("%s", weft::usage_text());
        return weft::exit_ok;
    }
    if (command_line.version) {
        std::printf("weft %s\n", WEFT_VERSION);
        return weft::exit_ok;
    }
    try {
        if (command_line.headless && command_line.replay_path)
            return weft::run_headless_replay(command_line);
        // No scene given: the default one, beside an installed weft or in the source tree.
        const std::string default_scene = weft::app::default_scene_path();
        if (command_line.headless) {
            weft::CommandLine with_scene = command_line;
            if (!with_scene.scene_path) with_scene.scene_path = default_scene;
            return weft::run_headless(with_scene);
        }
        return weft::app::run_demo_window(command_line, default_scene.c_str());
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "error: out of memory\n");
        return weft::exit_bad_input;
    }
}
