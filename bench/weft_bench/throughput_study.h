// weft-bench throughput: how fast weft steps and draws sheets of 32² to 256² particles with
// all spring families, beside a plain implementation of the same step and the machine's
// own limits (memory bandwidth, clearing the framebuffer), measured in the same process.
#pragma once

#include <string>
#include <vector>

namespace weft::bench {

struct ThroughputOptions {
    std::string scene;  // the material; resized to each sheet
    std::vector<std::string> overrides;
    std::string out_dir = ".";
    std::vector<int> sizes = {32, 64, 128, 256};  // particles per side
    // The demo's own 128² scene, drawn as the demo shows it (empty: not measured).
    std::string demo_scene;
};

int run_throughput_study(const ThroughputOptions& options);

}  // namespace weft::bench
