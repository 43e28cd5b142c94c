// The panel's answer to its last edit: which control made it and, when the scene loader
// refused the value, why. The panel draws the refusal right under that control, wrapped to the
// panel's width, until the next edit (written at the panel's foot, a refusal sat below the
// visible area, cut off, and the value just snapped back). ImGui-free, so the rule is tested.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace weft::app {

class LastEdit {
  public:
    // An edit by `control` (a name the panel gives it: the setting's key, such as
    // "springs.structural.stiffness") and the loader's error, or none when it was taken.
    void answer(std::string_view control, const std::optional<std::string>& error);
    // What to say under `control`: empty unless the last edit was that control's and was
    // refused.
    const std::string& refusal_under(std::string_view control) const;
    // Whether the last edit's refusal has yet to be seen: true the first time this is asked
    // after a refusal, false after that and after a taken edit. The panel scrolls a new
    // refusal whole into sight once (a control at the panel's foot left all but its first
    // line below the visible area), and no more, so the user can scroll away from it.
    bool newly_refused();

  private:
    std::string control_;  // the control that made the last edit
    std::string refusal_;  // its refusal as the panel says it; empty when it was taken
    bool unseen_ = false;  // refusal_ is not empty and newly_refused() has not been asked
};

// The loader's error as the panel says it next to the control: "refused: " and the reason,
// without the "error: --set KEY: " lead naming the setting the reader has just touched, and
// in ASCII (ascii_text) so the panel's font draws every sign.
std::string refusal_text(std::string_view error);

}  // namespace weft::app
