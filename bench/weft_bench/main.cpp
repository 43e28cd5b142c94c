// weft-bench: the speed-against-error studies.
//   weft-bench precision [SCENE.toml]... [--set K=V]... [--out DIR] [--repeats N]
//                        [--duration SECONDS]  (run length of scenes measured by invariants)
//   weft-bench invariants [SCENE.toml]... [--set K=V]... [--out DIR] [--repeats N]
//                         [--duration SECONDS]
//   weft-bench stability [SCENE.toml] [--sweep grid|mass|stiffness]... [--set K=V]...
//                        [--out DIR] [--duration SECONDS]
//   weft-bench throughput [SCENE.toml] [--set K=V]... [--out DIR] [--sizes N,N,...]
//   weft-bench replay SESSION.toml [--out DIR]
//   weft-bench realtime [SCENE.toml] [--set K=V]... [--out DIR] [--sizes N,N,...]
//                       [--duration SECONDS] [--max-run-seconds SECONDS]
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "invariant_study.h"
#include "precision_study.h"
#include "realtime_study.h"
#include "replay_study.h"
#include "stability_study.h"
#include "strict_number.h"
#include "study.h"
#include "throughput_study.h"

namespace {

// The usage text, on stderr after an error (status 2) or on stdout when asked for (status 0).
int usage(const char* problem) {
    if (problem) std::fprintf(stderr, "error: %s\n", problem);
    std::fprintf(
        problem ? stderr : stdout,
        "usage:\n"
        "  weft-bench precision [SCENE.toml]... [--set K=V]... [--out DIR] [--repeats N]\n"
        "                       [--duration SECONDS]\n"
        "  weft-bench invariants [SCENE.toml]... [--set K=V]... [--out DIR] [--repeats N]\n"
        "                        [--duration SECONDS]\n"
        "  weft-bench stability [SCENE.toml] [--sweep grid|mass|stiffness]... [--set K=V]...\n"
        "                       [--out DIR] [--duration SECONDS]\n"
        "  weft-bench throughput [SCENE.toml] [--set K=V]... [--out DIR] [--sizes N,N,...]\n"
        "  weft-bench replay SESSION.toml [--out DIR]\n"
        "  weft-bench realtime [SCENE.toml] [--set K=V]... [--out DIR] [--sizes N,N,...]\n"
        "                      [--duration SECONDS] [--max-run-seconds SECONDS]\n"
        "    each method at the 60 fps frame budget: weft's symplectic and implicit Euler,\n"
        "    XPBD with substeps and a plain float step; cost per frame, error, stretch\n"
        "    (default scene: cloth_128.toml if there is one, else large_sheet.toml;\n"
        "    sizes 32,64,128,256; duration 0.5 s; max-run-seconds 30)\n");
    return problem ? 2 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty())
        return usage(
            "which study? precision, invariants, stability, throughput, replay or realtime");
    if (std::find(args.begin(), args.end(), "--help") != args.end()) return usage(nullptr);
    const std::string study = args[0];
    std::vector<std::string> scenes, overrides, sweeps;
    std::string out_dir = "bench-out";
    int repeats = 3;
    std::optional<double> duration;         // s; each study has its own default
    std::optional<double> max_run_seconds;  // realtime: wall-clock cap of one method's run
    std::vector<int> sizes;  // throughput, realtime: particles per side (default: the study's own)
    for (std::size_t a = 1; a < args.size(); ++a) {
        const std::string& arg = args[a];
        const bool has_value = a + 1 < args.size();
        if (arg == "--set" && has_value)
            overrides.push_back(args[++a]);
        else if (arg == "--out" && has_value)
            out_dir = args[++a];
        else if (arg == "--sweep" && has_value)
            sweeps.push_back(args[++a]);
        else if (arg == "--repeats" && has_value) {
            std::string why;
            const auto value = weft::bench::parse_integer(args[++a], 1, 1000, why);
            if (!value) return usage(("--repeats: " + why).c_str());
            repeats = static_cast<int>(*value);
        } else if (arg == "--duration" && has_value) {
            std::string why;
            duration = weft::bench::parse_number_above(args[++a], 0.0, why);
            if (!duration) return usage(("--duration: " + why).c_str());
        } else if (arg == "--max-run-seconds" && has_value) {
            std::string why;
            max_run_seconds = weft::bench::parse_number_above(args[++a], 0.0, why);
            if (!max_run_seconds) return usage(("--max-run-seconds: " + why).c_str());
        } else if (arg == "--sizes" && has_value) {
            const std::string list = args[++a];
            for (std::size_t at = 0; at <= list.size();) {
                const std::size_t comma = std::min(list.find(',', at), list.size());
                std::string why;
                const auto side =
                    weft::bench::parse_integer(list.substr(at, comma - at), 3, 4096, why);
                if (!side) return usage(("--sizes: " + why).c_str());
                sizes.push_back(static_cast<int>(*side));
                at = comma + 1;
            }
        } else if (arg.rfind("--", 0) == 0)
            return usage(("unknown or incomplete option " + arg).c_str());
        else
            scenes.push_back(arg);
    }
    weft::bench::install_stop_handler();
    const std::string scenes_dir = WEFT_SCENES_DIR;
    if (study == "precision") {
        if (scenes.empty())
            scenes = {scenes_dir + "/hanging_sheet.toml", scenes_dir + "/stiff_sheet.toml"};
        return weft::bench::run_precision_study(
            {scenes, overrides, out_dir, repeats, duration.value_or(1.0)});
    }
    if (study == "invariants") {
        if (scenes.empty())
            scenes = {scenes_dir + "/tearing_sheet.toml", scenes_dir + "/sheet_on_sphere.toml"};
        return weft::bench::run_invariant_study(
            {scenes, overrides, out_dir, repeats, duration.value_or(1.0)});
    }
    if (study == "stability") {
        if (scenes.size() > 1) return usage("stability takes one scene");
        if (sweeps.empty()) sweeps = {"grid", "mass", "stiffness"};
        const std::string scene = scenes.empty() ? scenes_dir + "/hanging_sheet.toml" : scenes[0];
        return weft::bench::run_stability_study(
            {scene, overrides, sweeps, out_dir, duration.value_or(0.5)});
    }
    if (study == "throughput") {
        if (scenes.size() > 1) return usage("throughput takes one scene");
        const std::string scene = scenes.empty() ? scenes_dir + "/hanging_sheet.toml" : scenes[0];
        weft::bench::ThroughputOptions options{scene, overrides, out_dir};
        if (!sizes.empty()) options.sizes = sizes;
        options.demo_scene = scenes_dir + "/large_sheet.toml";
        return weft::bench::run_throughput_study(options);
    }
    if (study == "realtime") {
        if (scenes.size() > 1) return usage("realtime takes one scene");
        // The cloth-like material of issue 17 where it has landed, else the large sheet.
        const std::string cloth_like = scenes_dir + "/cloth_128.toml";
        const std::string scene = !scenes.empty() ? scenes[0]
                                  : std::filesystem::exists(cloth_like)
                                      ? cloth_like
                                      : scenes_dir + "/large_sheet.toml";
        weft::bench::RealtimeOptions options{scene, overrides, out_dir};
        if (!sizes.empty()) options.sizes = sizes;
        if (duration) options.duration = *duration;
        if (max_run_seconds) options.max_run_seconds = *max_run_seconds;
        return weft::bench::run_realtime_study(options);
    }
    if (study == "replay") {
        if (scenes.size() != 1) return usage("replay takes one recorded session (weft --record)");
        if (!overrides.empty()) return usage("replay replays the recorded parameters: no --set");
        return weft::bench::run_replay_study({scenes[0], out_dir});
    }
    return usage(("unknown study '" + study + "'").c_str());
}
