#include "app/screen_layout.h"

#include <algorithm>
#include <cmath>

namespace weft::app {

WindowLayout lay_out_window(float width, float height, bool panel_folded, float title_height) {
    constexpr float share = 0.3f, narrowest = 300.0f, widest = 400.0f;
    const float panel_width =
        std::floor(std::min(std::clamp(share * width, narrowest, widest), 0.5f * width));
    WindowLayout layout;
    if (panel_folded) {
        const float strip = std::min(title_height, height);
        layout.panel = {0.0f, 0.0f, panel_width, strip};
        layout.view = {0.0f, strip, width, height - strip};
    } else {
        layout.panel = {0.0f, 0.0f, panel_width, height};
        layout.view = {panel_width, 0.0f, width - panel_width, height};
    }
    return layout;
}

}  // namespace weft::app
