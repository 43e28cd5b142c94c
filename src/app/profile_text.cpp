#include "app/profile_text.h"

#include <cstdio>

namespace weft::app {

std::string profile_text(const StepProfile& profile, double dt, int threads) {
    std::string text;
    char line[160];
    const double steps = profile.steps > 0 ? static_cast<double>(profile.steps) : 1.0;
    std::snprintf(line, sizeof line,
                  "profile: %llu steps of %.4g ms on %d thread%s, %llu with the hand holding "
                  "the cloth, %llu in which it slipped\n",
                  static_cast<unsigned long long>(profile.steps), dt * 1e3, threads,
                  threads == 1 ? "" : "s", static_cast<unsigned long long>(profile.held_steps),
                  static_cast<unsigned long long>(profile.slips));
    text += line;
    const double total = profile.seconds.total();
    text += "  phase                 total s   ms a step   share\n";
    const struct {
        const char* name;
        double seconds;
    } phases[] = {{"integrate", profile.seconds.integrate},
                  {"  implicit setup", profile.seconds.implicit.setup},
                  {"  coarse levels", profile.seconds.implicit.coarse_levels},
                  {"  CG iterations", profile.seconds.implicit.iterations},
                  {"  split checks", profile.seconds.implicit.split_checks},
                  {"strain limit", profile.seconds.strain_limit},
                  {"contacts and hand", profile.seconds.contacts},
                  {"tearing", profile.seconds.tearing},
                  {"guards", profile.seconds.guards},
                  {"all", total}};
    const bool implicit = profile.seconds.implicit.total() > 0.0;
    for (const auto& phase : phases) {
        if (phase.name[0] == ' ' && !implicit) continue;  // implicit Euler's part of integrate
        std::snprintf(line, sizeof line, "  %-18s %10.4f %11.4f %6.1f %%\n", phase.name,
                      phase.seconds, phase.seconds / steps * 1e3,
                      total > 0.0 ? 100.0 * phase.seconds / total : 0.0);
        text += line;
    }
    std::snprintf(line, sizeof line, "  force evaluations: %llu (%.3g a step)\n",
                  static_cast<unsigned long long>(profile.force_evaluations),
                  static_cast<double>(profile.force_evaluations) / steps);
    text += line;
    if (profile.solver_iterations > 0 || profile.splits > 0) {
        std::snprintf(line, sizeof line,
                      "  implicit solve: %llu iterations (%.3g a step, at most %d), %llu splits "
                      "(at most %d in a step)\n",
                      static_cast<unsigned long long>(profile.solver_iterations),
                      static_cast<double>(profile.solver_iterations) / steps,
                      profile.most_iterations, static_cast<unsigned long long>(profile.splits),
                      profile.most_splits);
        text += line;
    }
    return text;
}

}  // namespace weft::app
