#include "app/command_line.h"

#include <charconv>
#include <cmath>

#include "sim/scene/scene.h"

namespace weft {
namespace {

// Parses all of `text` as a base-10 unsigned integer, or nothing.
std::optional<std::uint64_t> parse_unsigned(const std::string& text) {
    std::uint64_t value = 0;
    const char* end = text.data() + text.size();
    auto [stop, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || stop != end) return std::nullopt;
    return value;
}

// Screenshots larger than 16384 pixels a side would need gigabytes of framebuffer.
constexpr std::uint64_t max_image_side = 16384;
// More frames a second of simulated time than any slow motion needs.
constexpr std::uint64_t max_frames_per_second = 1000;

}  // namespace

std::variant<CommandLine, CommandLineError> parse_command_line(
    const std::vector<std::string>& args) {
    CommandLine line;
    bool fps_given = false;
    for (std::size_t a = 0; a < args.size(); ++a) {
        const std::string& arg = args[a];
        // Options that take a value accept it as the next argument or after '='.
        auto take_value = [&](const std::string& option) -> std::optional<std::string> {
            if (arg.size() > option.size() && arg[option.size()] == '=')
                return arg.substr(option.size() + 1);
            if (arg != option || a + 1 >= args.size()) return std::nullopt;
            return args[++a];
        };
        auto is_option = [&](const std::string& option) {
            return arg == option || arg.rfind(option + "=", 0) == 0;
        };
        if (arg == "--help" || arg == "-h") {
            line.help = true;
        } else if (arg == "--version") {
            line.version = true;
        } else if (arg == "--headless") {
            line.headless = true;
        } else if (arg == "--profile") {
            line.profile = true;
        } else if (is_option("--set")) {
            auto value = take_value("--set");
            if (!value) return CommandLineError{"--set", "expects KEY=VALUE"};
            line.overrides.push_back(*value);
        } else if (is_option("--steps")) {
            auto value = take_value("--steps");
            auto steps = value ? parse_unsigned(*value) : std::nullopt;
            if (!steps)
                return CommandLineError{"--steps", "expects a whole number of steps >= 0, got '" +
                                                       value.value_or("") + "'"};
            line.steps = steps;
        } else if (is_option("--dump")) {
            auto value = take_value("--dump");
            if (!value || value->empty()) return CommandLineError{"--dump", "expects a file name"};
            line.dump_path = value;
        } else if (is_option("--obj")) {
            auto value = take_value("--obj");
            if (!value || value->empty()) return CommandLineError{"--obj", "expects a file name"};
            line.obj_path = value;
        } else if (is_option("--frames")) {
            auto value = take_value("--frames");
            if (!value || value->empty())
                return CommandLineError{"--frames", "expects a folder name"};
            line.frames_dir = value;
        } else if (is_option("--fps")) {
            auto value = take_value("--fps");
            auto fps = value ? parse_unsigned(*value) : std::nullopt;
            if (!fps || *fps < 1 || *fps > max_frames_per_second)
                return CommandLineError{"--fps",
                                        "expects a whole number of frames a second from 1 to "
                                        "1000, got '" +
                                            value.value_or("") + "'"};
            line.frames_per_second = static_cast<int>(*fps);
            fps_given = true;
        } else if (is_option("--screenshot")) {
            auto value = take_value("--screenshot");
            if (!value || value->empty())
                return CommandLineError{"--screenshot", "expects a file name"};
            line.screenshot_path = value;
        } else if (is_option("--size")) {
            auto value = take_value("--size");
            const std::string text = value.value_or("");
            const auto x = text.find('x');
            auto width = x == std::string::npos ? std::nullopt : parse_unsigned(text.substr(0, x));
            auto height =
                x == std::string::npos ? std::nullopt : parse_unsigned(text.substr(x + 1));
            if (!width || !height || *width < 1 || *height < 1 || *width > max_image_side ||
                *height > max_image_side)
                return CommandLineError{"--size",
                                        "expects WxH with 1 <= W, H <= 16384, got '" + text + "'"};
            line.screenshot_width = static_cast<int>(*width);
            line.screenshot_height = static_cast<int>(*height);
        } else if (is_option("--record") || is_option("--replay")) {
            const std::string option = is_option("--record") ? "--record" : "--replay";
            auto value = take_value(option);
            if (!value || value->empty()) return CommandLineError{option, "expects a file name"};
            (option == "--record" ? line.record_path : line.replay_path) = value;
        } else if (is_option("--compare")) {
            auto value = take_value("--compare");
            const std::string text = value.value_or("");
            const auto equals = text.find('=');
            CommandLine::Comparison comparison{text.substr(0, equals), 0.0};
            if (!integrator_from_name(comparison.integrator))
                return CommandLineError{"--compare",
                                        "expects METHOD[=DT] with METHOD one of explicit-euler, "
                                        "symplectic-euler, verlet, velocity-verlet, rk4, "
                                        "implicit-euler; got '" +
                                            text + "'"};
            if (equals != std::string::npos) {
                const std::string dt_text = text.substr(equals + 1);
                const char* end = dt_text.data() + dt_text.size();
                auto [stop, error] = std::from_chars(dt_text.data(), end, comparison.dt);
                if (dt_text.empty() || error != std::errc() || stop != end ||
                    !(comparison.dt > 0.0) || !std::isfinite(comparison.dt))
                    return CommandLineError{
                        "--compare",
                        "expects a dt in seconds > 0 after '=', got '" + dt_text + "'"};
            }
            line.comparisons.push_back(comparison);
        } else if (arg.rfind("-", 0) == 0 && arg.size() > 1) {
            return CommandLineError{arg, "unknown option (see weft --help)"};
        } else if (line.scene_path) {
            return CommandLineError{
                arg, "only one scene file can be given (already have '" + *line.scene_path + "')"};
        } else {
            line.scene_path = arg;
        }
    }
    if (line.help || line.version) return line;
    if (fps_given && !line.frames_dir)
        return CommandLineError{"--fps", "only applies with --frames DIR"};
    if (line.replay_path) {
        // A recording carries its scene and its length.
        if (line.scene_path)
            return CommandLineError{*line.scene_path,
                                    "--replay takes the scene from the recording; give no scene"};
        if (!line.overrides.empty())
            return CommandLineError{"--set", "--replay replays the recorded parameters; no --set"};
        if (line.steps) return CommandLineError{"--steps", "--replay runs the recorded steps"};
        if (line.record_path) return CommandLineError{"--record", "cannot record a replay"};
    }
    if (line.headless) {
        if (line.replay_path) return line;
        if (!line.steps) return CommandLineError{"--headless", "needs --steps N"};
        if (line.record_path) return CommandLineError{"--record", "only applies in the window"};
    } else {
        // The window takes --dump (written when it closes) and --size (its size).
        const char* headless_only = line.steps             ? "--steps"
                                    : line.screenshot_path ? "--screenshot"
                                    : line.obj_path        ? "--obj"
                                    : line.frames_dir      ? "--frames"
                                    : line.profile         ? "--profile"
                                                           : nullptr;
        if (headless_only) return CommandLineError{headless_only, "only applies with --headless"};
    }
    return line;
}

const char* usage_text() {
    return "usage:\n"
           "  weft [SCENE.toml] [--set KEY=VALUE]... [--compare METHOD[=DT]]... [--record FILE]\n"
           "  weft --replay SESSION.toml [--compare METHOD[=DT]]...\n"
           "  weft --headless [SCENE.toml] --steps N [--set KEY=VALUE]... [--dump STATE.csv]\n"
           "       [--obj CLOTH.obj] [--frames DIR [--fps N]] [--profile]\n"
           "       [--screenshot IMAGE.png [--size WxH] [--compare METHOD[=DT]]...]\n"
           "  weft --headless --replay SESSION.toml [--dump STATE.csv] [--obj CLOTH.obj]\n"
           "       [--frames DIR [--fps N]] [--profile]\n"
           "       [--screenshot IMAGE.png [--size WxH] [--compare METHOD[=DT]]...]\n"
           "  weft --help | --version\n"
           "\n"
           "  SCENE.toml        a scene file; none: the default, hanging_sheet.toml, from the\n"
           "                    shipped scenes (installed: BINDIR/../share/weft/scenes)\n"
           "  --set KEY=VALUE   override a scene key by its dotted path, e.g. solver.dt=0.0005\n"
           "  --steps N         run exactly N steps of the scene's dt (headless)\n"
           "  --dump FILE       write row,col,x,y,z,vx,vy,vz per particle after the run\n"
           "                    (in the window: when it closes)\n"
           "  --obj FILE        write the cloth after the run as Wavefront OBJ: a v line per\n"
           "                    particle in the dump's order, an f line per intact triangle\n"
           "  --frames DIR      write DIR/frame-00000.png, ... one per 1/30 s of simulated\n"
           "                    time from the start, at --size, with the --compare copies\n"
           "  --fps N           frames a second of simulated time for --frames (1-1000)\n"
           "  --profile         after the run, print where the steps' time went, phase by\n"
           "                    phase, and the solver's iterations and splits (headless)\n"
           "  --size WxH        screenshot size, or the window's (default 1280x720)\n"
           "  --compare M[=DT]  show a copy of the scene beside it, stepped by integrator M\n"
           "                    (at DT seconds; default the scene's dt), fed the same hand;\n"
           "                    headless, drawn beside it in the screenshot\n"
           "  --record FILE     record the window's session (hand, panel) to FILE on quit\n"
           "  --replay FILE     replay a recorded session; headless, it reports whether the\n"
           "                    final state is bit for bit the recorded one\n"
           "\n"
           "exit status: 0 done, 2 bad input, 3 the simulation diverged,\n"
           "             4 a headless replay did not reproduce the recorded state\n";
}

}  // namespace weft
