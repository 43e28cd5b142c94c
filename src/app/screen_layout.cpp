#include "app/screen_layout.h"

#include <algorithm>

namespace weft::app {

ScreenRect area_beside_panel(const ScreenRect& window, const ScreenRect& panel, float narrowest) {
    // The panel can be dragged partly off the window: only what lies inside it takes room.
    const float panel_left = std::clamp(panel.x, window.x, window.right());
    const float panel_right = std::clamp(panel.right(), window.x, window.right());
    const float left_width = panel_left - window.x;
    const float right_width = window.right() - panel_right;
    ScreenRect area = window;
    if (right_width >= left_width) {
        area.x = panel_right;
        area.width = right_width;
    } else {
        area.width = left_width;
    }
    return area.width >= narrowest ? area : window;
}

}  // namespace weft::app
