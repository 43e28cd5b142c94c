#include "app/profile_text.h"

#include <cstdio>
#include <vector>

namespace weft::app {
namespace {

struct Phase {
    const char* name;  // indented: a part of the phase above
    double seconds;
};

// The rows both texts print, implicit Euler's parts only where it ran.
std::vector<Phase> phases_of(const StepProfile& profile) {
    const StepTimes& s = profile.seconds;
    std::vector<Phase> rows{{"integrate", s.integrate}};
    if (s.implicit.total() > 0.0) {
        rows.push_back({"  implicit setup", s.implicit.setup});
        rows.push_back({"  coarse levels", s.implicit.coarse_levels});
        rows.push_back({"  CG iterations", s.implicit.iterations});
        rows.push_back({"  split checks", s.implicit.split_checks});
    }
    rows.insert(rows.end(), {{"strain limit", s.strain_limit},
                             {"contacts and hand", s.contacts},
                             {"tearing", s.tearing},
                             {"guards", s.guards},
                             {"all", s.total()}});
    return rows;
}

}  // namespace

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
    for (const Phase& phase : phases_of(profile)) {
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
                      "(at most %d in a step), %llu Newton iterations, %llu tries stopped at "
                      "the early judgement\n",
                      static_cast<unsigned long long>(profile.solver_iterations),
                      static_cast<double>(profile.solver_iterations) / steps,
                      profile.most_iterations, static_cast<unsigned long long>(profile.splits),
                      profile.most_splits,
                      static_cast<unsigned long long>(profile.newton_iterations),
                      static_cast<unsigned long long>(profile.tries_stopped_early));
        text += line;
    }
    return text;
}

std::string profile_panel_text(const StepProfile& profile) {
    std::string text;
    char line[96];
    const double steps = profile.steps > 0 ? static_cast<double>(profile.steps) : 1.0;
    std::snprintf(line, sizeof line, "%llu steps, %llu held by the hand\n",
                  static_cast<unsigned long long>(profile.steps),
                  static_cast<unsigned long long>(profile.held_steps));
    text += line;
    const double total = profile.seconds.total();
    for (const Phase& phase : phases_of(profile)) {
        std::snprintf(line, sizeof line, "%-18s %7.3f ms %4.0f %%\n", phase.name,
                      phase.seconds / steps * 1e3,
                      total > 0.0 ? 100.0 * phase.seconds / total : 0.0);
        text += line;
    }
    if (profile.solver_iterations > 0 || profile.splits > 0) {
        std::snprintf(line, sizeof line, "a step: %.3g CG iterations, %.2g splits\n",
                      static_cast<double>(profile.solver_iterations) / steps,
                      static_cast<double>(profile.splits) / steps);
        text += line;
    }
    return text;
}

}  // namespace weft::app
