#include "app/window_state_file.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace weft::app {

std::string window_state_text(long long frames_drawn, const DemoState& state) {
    std::ostringstream out;
    out.precision(17);
    out << "frames " << frames_drawn << '\n'
        << "steps " << state.simulation().steps_taken() << '\n'
        << "time " << state.simulation().time() << '\n'
        << "paused " << (state.paused ? 1 : 0) << '\n'
        << "held " << (state.simulation().grab().active() ? 1 : 0) << '\n';
    return out.str();
}

bool write_window_state(const std::string& path, long long frames_drawn, const DemoState& state) {
    std::string temporary = path;
    temporary.append(".tmp");
    {
        std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
        file << window_state_text(frames_drawn, state);
        if (!file) return false;
    }
    return std::rename(temporary.c_str(), path.c_str()) == 0;
}

}  // namespace weft::app
