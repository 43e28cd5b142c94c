#include "app/edit_answer.h"

#include "app/status_text.h"

namespace weft::app {

void LastEdit::answer(std::string_view control, const std::optional<std::string>& error) {
    control_ = control;
    refusal_ = error ? refusal_text(*error) : std::string();
    unseen_ = !refusal_.empty();
}

bool LastEdit::newly_refused() {
    const bool unseen = unseen_;
    unseen_ = false;
    return unseen;
}

const std::string& LastEdit::refusal_under(std::string_view control) const {
    static const std::string nothing;
    return control == control_ ? refusal_ : nothing;
}

std::string refusal_text(std::string_view error) {
    // The loader's messages read "error: --set KEY: WHY" for an override.
    for (std::string_view lead : {"error: ", "--set "}) {
        if (error.substr(0, lead.size()) != lead) continue;
        error.remove_prefix(lead.size());
        if (lead == "--set ") {
            const std::size_t colon = error.find(": ");
            if (colon != std::string_view::npos) error.remove_prefix(colon + 2);
        }
    }
    // In signs the panel's font draws: the grid's limit reads "cloth.rows x cloth.cols".
    return "refused: " + ascii_text(error);
}

}  // namespace weft::app
