#include "sim/build/spring_coloring.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

namespace weft {

void colour_springs(SpringGroup& group, std::size_t particle_count) {
    // Colours already used at each particle, as bits; a regular grid needs fewer than 16,
    // and a spring whose ends have used all 64 goes to a last, serial colour.
    std::vector<std::uint64_t> used(particle_count, 0);
    std::vector<std::uint8_t> colour(group.springs.size());
    constexpr int serial_colour = 64;
    for (std::size_t s = 0; s < group.springs.size(); ++s) {
        const Spring& spring = group.springs[s];
        const std::uint64_t taken = used[spring.i] | used[spring.j];
        const int c = taken == ~std::uint64_t{0} ? serial_colour : std::countr_one(taken);
        colour[s] = static_cast<std::uint8_t>(c);
        if (c < serial_colour) {
            used[spring.i] |= std::uint64_t{1} << c;
            used[spring.j] |= std::uint64_t{1} << c;
        }
    }
    // Counting sort by colour, stable.
    std::vector<std::uint32_t> starts(serial_colour + 2, 0);
    for (std::uint8_t c : colour) ++starts[c + 1];
    for (std::size_t c = 1; c < starts.size(); ++c) starts[c] += starts[c - 1];
    std::vector<Spring> sorted(group.springs.size());
    std::vector<std::uint32_t> next(starts.begin(), starts.end() - 1);
    for (std::size_t s = 0; s < group.springs.size(); ++s)
        sorted[next[colour[s]]++] = group.springs[s];
    group.springs = std::move(sorted);
    // The first spring of every colour in use, then the end of the parallel colours, which is
    // where the serial remainder starts.
    group.colour_starts.clear();
    for (int c = 0; c < serial_colour; ++c)
        if (starts[c] < starts[c + 1]) group.colour_starts.push_back(starts[c]);
    group.colour_starts.push_back(starts[serial_colour]);
}

}  // namespace weft
