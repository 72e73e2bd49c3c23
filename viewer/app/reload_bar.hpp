#pragma once
// The reload choice, across the top of the image: the file changed on disk
// (or was reloaded) while there are unsaved edits, and nothing happens until
// the user says which to keep. It can show the differences between the
// viewer's text and the file's, line by line (text_diff.hpp).

#include "model/app_state.hpp"
#include "model/image_layout.hpp"
#include "model/text_diff.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace jt::view {

struct ReloadBarState {
    bool show_differences = false;
    // What `diff` was made from, remade only when one changes: the document
    // at a revision and file generation with its draft, and the files' newer
    // texts (the scene file's, then each included file's). Not the document's
    // text itself: making it writes the panel edits into the base text, a copy
    // of the whole file every frame.
    std::optional<std::uint64_t> revision;
    std::uint64_t generation = 0;
    std::optional<std::string> draft;
    std::string theirs;
    std::vector<std::string> theirs_included;
    TextDiff diff;  // reload_differences
};

// Draws the bar at the top of `area` while a reload waits for the choice;
// returns how much of the area's height it takes (0 when there is none).
float reload_bar(AppState& state, ReloadBarState& bar, const ScreenRect& area);

}  // namespace jt::view
