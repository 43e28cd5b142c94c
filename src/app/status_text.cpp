#include "app/status_text.h"

#include <cstdio>

namespace weft::app {

std::string counted(long long count, std::string_view singular, std::string_view plural) {
    return std::to_string(count) + " " + std::string(count == 1 ? singular : plural);
}

std::string linear_solve_text(const Simulation::LinearSolve& solve) {
    char residual[32];
    std::snprintf(residual, sizeof residual, "%.1e", solve.relative_residual);
    return "solve: " + counted(solve.iterations, "iteration", "iterations") + ", residual " +
           residual;
}

std::optional<std::string> linear_solve_text(const Simulation& simulation) {
    if (simulation.integrator() != Integrator::implicit_euler) return std::nullopt;
    // At t = 0 nothing has been solved (after a reset the workspace may still hold the last
    // run's numbers), so there is nothing true to show yet.
    if (simulation.time() == 0.0) return std::string("solve: none yet");
    return linear_solve_text(simulation.last_linear_solve());
}

}  // namespace weft::app
