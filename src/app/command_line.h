// The command line of `weft` (contract in the design notes, extended):
//   weft [SCENE.toml] [--set KEY=VALUE]... [--compare METHOD[=DT]]... [--record FILE]
//   weft --replay SESSION.toml [--compare METHOD[=DT]]...
//   weft --headless [SCENE.toml] --steps N [--set KEY=VALUE]... [--dump STATE.csv]
//        [--obj CLOTH.obj] [--frames DIR [--fps N]]
//        [--screenshot IMAGE.png [--size WxH] [--compare METHOD[=DT]]...]
//   weft --headless --replay SESSION.toml [--dump STATE.csv] [--obj CLOTH.obj]
//        [--screenshot IMAGE.png [--size WxH] [--compare METHOD[=DT]]...]
//   weft --help | --version
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace weft {

struct CommandLine {
    bool headless = false;
    bool help = false;
    bool version = false;                   // --version: print the version and stop
    std::optional<std::string> scene_path;  // absent: the default scene
    std::vector<std::string> overrides;     // "KEY=VALUE", in order
    std::optional<std::uint64_t> steps;     // --steps N
    std::optional<std::string> dump_path;   // --dump FILE.csv
    std::optional<std::string> obj_path;    // --obj FILE.obj: the final cloth as a mesh
    std::optional<std::string> frames_dir;  // --frames DIR: DIR/frame-00000.png, ...
    int frames_per_second = 30;             // --fps N: frames per second of simulated time
    bool profile = false;                   // --profile: time and counters per phase, on stdout
    std::optional<std::string> screenshot_path;
    int screenshot_width = 1280;  // pixels, --size WxH
    int screenshot_height = 720;
    std::optional<std::string> record_path;  // --record FILE: the window's session, on quit
    std::optional<std::string> replay_path;  // --replay FILE
    // --compare METHOD[=DT]: runs shown beside the main one, each with its integrator (scene
    // spelling) and dt in seconds (0: the scene's).
    struct Comparison {
        std::string integrator;
        double dt = 0.0;
    };
    std::vector<Comparison> comparisons;
};

struct CommandLineError {
    std::string where;  // the option at fault, e.g. "--steps"
    std::string what;
};

std::variant<CommandLine, CommandLineError> parse_command_line(
    const std::vector<std::string>& args);

const char* usage_text();

}  // namespace weft
