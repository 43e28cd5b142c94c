// Short lines of text the demo and the command line show about a run: counts with their noun
// in the right number, implicit Euler's linear solve, and text as the window's font can draw
// it. SDL-free, so the wording is tested.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "sim/core/simulation.h"

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

// The panel's strain line, from the largest ratio of a spring's length to its rest length:
// "most stretched spring: rest + 37.6 %" ("rest - 2.0 %" when every spring is compressed;
// "none (no springs)" for a NaN ratio), short enough for the narrowest panel's line. A bare
// "largest stretch 37.6 %" at rest left a newcomer wondering what was stretched, and over
// what.
std::string stretch_text(double largest_stretch_ratio);
// Where that spring is, for the line under it: "at (row 1, col 0), by a pin" (on a mesh
// "at vertex 12"), naming its end that is free to move. At rest the most
// stretched springs are the ones holding the sheet up: next to its pins.
std::string stretch_place_text(const Cloth& cloth, const Spring& spring);

// `utf8` with the signs weft's messages use spelled in ASCII ("—" as "-", "×" as "x", "²" as
// "2", "·" as ".", "…" as "...", "Δ" as "d", "°" as " deg"): the window's font (Dear ImGui's
// default, ProggyClean) has no glyph for them and would draw "?". Anything else is kept.
std::string ascii_text(std::string_view utf8);

}  // namespace weft::app
