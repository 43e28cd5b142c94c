// weft-bench replay SESSION.toml: a recorded session (a drag, cuts, parameter changes, as
// the demo recorded them) replayed as a hard case by every integrator in turn, through the
// demo's own stepping and recovery. The recorded integrator must end in the recorded state
// bit for bit; each other one reports how it fared on the same hand: the divergences it
// recovered from, the dt it ended at, its final energy and largest stretch, its CPU time.
#pragma once

#include <string>

namespace weft::bench {

struct ReplayOptions {
    std::string session_path;
    std::string out_dir;
};

// Writes replay.csv into out_dir; returns the exit status (0, 2 bad input, 4 the recorded
// integrator did not reproduce the recording, 130 stopped).
int run_replay_study(const ReplayOptions& options);

}  // namespace weft::bench
