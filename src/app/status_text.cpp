#include "app/status_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

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

std::string stretch_text(double largest_stretch_ratio) {
    if (!std::isfinite(largest_stretch_ratio)) return "most stretched spring: none (no springs)";
    const double percent = 100.0 * (largest_stretch_ratio - 1.0);
    char text[96];
    std::snprintf(text, sizeof text, "most stretched spring: rest %c %.1f %%",
                  percent < 0.0 ? '-' : '+', std::abs(percent));
    return text;
}

std::string stretch_place_text(const Cloth& cloth, const Spring& spring) {
    const std::size_t count = cloth.particle_count();
    if (spring.i >= count || spring.j >= count) return {};
    const bool i_pinned = cloth.is_pinned(spring.i), j_pinned = cloth.is_pinned(spring.j);
    const std::uint32_t free_end = i_pinned ? spring.j : spring.i;
    // "particle" goes without saying under "most stretched spring", and the line must fit
    // the narrowest panel without wrapping (the rows under it would move).
    std::string name = particle_name(cloth, free_end);
    constexpr std::string_view particle = "particle ";
    if (name.starts_with(particle)) name.erase(0, particle.size());
    return "at " + name + (i_pinned || j_pinned ? ", by a pin" : "");
}

std::string ascii_text(std::string_view utf8) {
    struct Spelling {
        std::string_view sign, ascii;
    };
    static constexpr Spelling spellings[] = {
        {"\u2014", "-"}, {"\u2013", "-"},   {"\u00d7", "x"},  {"\u00b2", "2"},    {"\u00b3", "3"},
        {"\u00b7", "."}, {"\u2026", "..."}, {"\u0394", "d"},  {"\u00b0", " deg"}, {"\u2212", "-"},
        {"\u2248", "~"}, {"\u2264", "<="},  {"\u2265", ">="},
    };
    std::string text;
    text.reserve(utf8.size());
    for (std::size_t at = 0; at < utf8.size();) {
        if (static_cast<unsigned char>(utf8[at]) < 0x80) {  // ASCII: as it is
            text += utf8[at++];
            continue;
        }
        const auto spelled = std::find_if(
            std::begin(spellings), std::end(spellings),
            [&](const Spelling& s) { return utf8.substr(at, s.sign.size()) == s.sign; });
        if (spelled == std::end(spellings)) {
            text += utf8[at++];
        } else {
            text += spelled->ascii;
            at += spelled->sign.size();
        }
    }
    return text;
}

}  // namespace weft::app
