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
//   weft-bench --help | --version,  weft-bench STUDY --help | --version
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/scene_folder.h"
#include "invariant_study.h"
#include "precision_study.h"
#include "realtime_study.h"
#include "replay_study.h"
#include "stability_study.h"
#include "strict_number.h"
#include "study.h"
#include "throughput_study.h"

namespace {

// Each study's synopsis and what it measures: `weft-bench --help` prints every synopsis,
// `weft-bench STUDY --help` one study's whole entry.
struct StudyHelp {
    const char* name;
    const char* synopsis;
    const char* description;
};

constexpr StudyHelp studies[] = {
    {"precision",
     "  weft-bench precision [SCENE.toml]... [--set K=V]... [--out DIR] [--repeats N]\n"
     "                       [--duration SECONDS]\n",
     "Work-precision diagrams: every integrator's error against an RK4 reference, against CPU\n"
     "time per simulated second and against dt, with the fitted order (default scenes:\n"
     "hanging_sheet and stiff_sheet). Scenes with tearing or contacts have no trajectory to\n"
     "converge to and are measured by their invariants instead.\n"
     "  --repeats N         timed runs per point, their median (1 to 1000, default 3)\n"
     "  --duration SECONDS  simulated time of each invariant run (default 1)\n"},
    {"invariants",
     "  weft-bench invariants [SCENE.toml]... [--set K=V]... [--out DIR] [--repeats N]\n"
     "                        [--duration SECONDS]\n",
     "Energy change, largest strain, sag, springs torn and contacts per integrator and dt, for\n"
     "scenes with tearing or contacts (default: tearing_sheet and sheet_on_sphere).\n"
     "  --repeats N         timed runs per point, the least (1 to 1000, default 3)\n"
     "  --duration SECONDS  simulated time of each run (default 1)\n"},
    {"stability",
     "  weft-bench stability [SCENE.toml] [--sweep grid|mass|stiffness]... [--set K=V]...\n"
     "                       [--out DIR] [--duration SECONDS]\n",
     "Each integrator's largest stable dt by bisection beside the linear prediction, swept over\n"
     "grid size, particle mass and stiffness (default scene: hanging_sheet; all sweeps).\n"
     "  --duration SECONDS  simulated time a step must survive (default 0.5)\n"},
    {"throughput",
     "  weft-bench throughput [SCENE.toml] [--set K=V]... [--out DIR] [--sizes N,N,...]\n",
     "Step and draw times of sheets of each size against a plain implementation, and real\n"
     "time at 60 frames per second (default scene: hanging_sheet).\n"
     "  --sizes N,N,...     particles per side (3 to 4096, default 32,64,128,256)\n"},
    {"replay", "  weft-bench replay SESSION.toml [--out DIR]\n",
     "Replays a recorded session (weft --record) with every integrator in turn, as a hard case.\n"},
    {"realtime",
     "  weft-bench realtime [SCENE.toml] [--set K=V]... [--out DIR] [--sizes N,N,...]\n"
     "                      [--duration SECONDS] [--max-run-seconds SECONDS]\n",
     "Each method at the 60 fps frame budget: weft's symplectic Euler (also with its spring\n"
     "forces in float) and implicit Euler, XPBD with substeps and a plain float step; cost per\n"
     "frame, error, stretch (default scene:\n"
     "cloth_128.toml if there is one, else large_rubber_sheet.toml).\n"
     "  --sizes N,N,...     particles per side (3 to 4096, default 32,64,128,256)\n"
     "  --duration SECONDS  simulated time of each run (default 0.5)\n"
     "  --max-run-seconds SECONDS  wall-clock cap of one method's run (default 30)\n"},
};

const char* const set_option =
    "  --set K=V           override a scene key, checked like the file (weft --help)\n";
const char* const out_option =
    "  --out DIR           where the CSV files and plots go (default bench-out)\n";

void print_synopses(std::FILE* out) {
    std::fprintf(out, "usage:\n");
    for (const StudyHelp& study : studies) std::fprintf(out, "%s", study.synopsis);
    std::fprintf(out,
                 "  weft-bench --help | --version\n"
                 "  weft-bench STUDY --help | --version\n");
}

int usage(const char* problem) {
    if (problem) std::fprintf(stderr, "error: %s\n", problem);
    print_synopses(stderr);
    return 2;
}

const StudyHelp* find_study(const std::string& name) {
    for (const StudyHelp& study : studies)
        if (name == study.name) return &study;
    return nullptr;
}

bool is_help(const std::string& arg) {
    return arg == "--help" || arg == "-h";
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty())
        return usage(
            "which study? precision, invariants, stability, throughput, replay or realtime");
    if (is_help(args[0])) {
        print_synopses(stdout);
        std::printf(
            "\nCSV files with a header line, and a PNG plot of each, go into --out.\n"
            "`weft-bench STUDY --help` tells what a study measures.\n");
        return 0;
    }
    if (args[0] == "--version") {
        std::printf("weft-bench %s\n", WEFT_VERSION);
        return 0;
    }
    const std::string study = args[0];
    const StudyHelp* help = find_study(study);
    if (!help) return usage(("unknown study '" + study + "'").c_str());
    // Asked for help, a study explains itself whatever else the line holds.
    if (std::any_of(args.begin() + 1, args.end(), is_help)) {
        std::printf("usage:\n%s\n%s", help->synopsis, help->description);
        // replay replays the recorded parameters: it takes no --set.
        if (std::strstr(help->synopsis, "--set")) std::printf("%s", set_option);
        std::printf("%s", out_option);
        return 0;
    }
    // Every study is part of the same program, of the same version.
    if (std::find(args.begin() + 1, args.end(), "--version") != args.end()) {
        std::printf("weft-bench %s\n", WEFT_VERSION);
        return 0;
    }
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
    const std::string scenes_dir = weft::app::shipped_scenes_folder();
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
        options.demo_scene = scenes_dir + "/large_rubber_sheet.toml";
        return weft::bench::run_throughput_study(options);
    }
    if (study == "realtime") {
        if (scenes.size() > 1) return usage("realtime takes one scene");
        // The cloth-like material where it has landed, else the large sheet.
        const std::string cloth_like = scenes_dir + "/cloth_128.toml";
        const std::string scene = !scenes.empty() ? scenes[0]
                                  : std::filesystem::exists(cloth_like)
                                      ? cloth_like
                                      : scenes_dir + "/large_rubber_sheet.toml";
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
    return usage(("unknown study '" + study + "'").c_str());  // a study in the table, not run here
}
