// Short lines of text the demo and the command line show about a run: counts with their noun
// in the right number, and implicit Euler's linear solve. SDL-free, so the wording is tested.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "sim/simulation.h"

namespace weft::app {

// "1 time", "0 times", "3 times": the count and its noun, singular only for exactly one.
std::string counted(long long count, std::string_view singular, std::string_view plural);

// "solve: 23 iterations, residual 4.1e-03": conjugate gradient's iterations and its relative
// residual |A Δv - b| / |b| to two significant digits, the precision the eye compares.
std::string linear_solve_text(const Simulation::LinearSolve& solve);

// The line above for a run stepped by implicit Euler ("solve: none yet" before its first
// step, when there is no solve to report); nothing for the explicit integrators, which
// solve no system.
std::optional<std::string> linear_solve_text(const Simulation& simulation);

}  // namespace weft::app
