// weft-bench realtime: speed against error at the 60 fps frame budget.
// For sheets of one material at several sizes, each method at a few settings: the CPU time
// of one simulated 1/60 s frame, whether that and drawing the frame at 1280x720 fit in
// 1/60 s, the error against a converged reference of the same sheet, and the largest
// stretch. The methods are weft's symplectic Euler at its step limit, weft's implicit Euler
// at frame-sized steps, and what a user would pick instead: XPBD with substeps (as Jolt
// Physics' soft body) and a plain float symplectic Euler step.
#pragma once

#include <string>
#include <vector>

namespace weft::bench {

struct RealtimeOptions {
    std::string scene;  // the material; resized to each sheet
    std::vector<std::string> overrides;
    std::string out_dir = ".";
    std::vector<int> sizes = {32, 64, 128, 256};  // particles per side
    double duration = 0.5;                        // s simulated, from the scene's start
    // Wall-clock seconds after which one method's run is cut short: its cost per frame is
    // still measured, its error is not (a slow setting must not hold up the study).
    double max_run_seconds = 30.0;
};

int run_realtime_study(const RealtimeOptions& options);

}  // namespace weft::bench
