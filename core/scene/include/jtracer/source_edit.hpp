#pragma once
// Writes an edited Scene back into the .jts text it was parsed from, touching
// only what changed: each changed value is replaced at its span, a property
// that was never written is inserted into its block, a new camera is appended
// to the last `cameras` block, and cameras removed from the end lose their
// blocks. Every other byte (comments, order, spacing) stays as it was, down to
// the components of a vector that did not change (`<-5.0, 8.0, 6.0>` with a
// new x keeps `8.0, 6.0`). Values are written as value_text.hpp writes them.
// The viewer's "Save scene" uses it. A value read from an included file is
// edited in that file's text (SourceEditResult::files), in place too.

#include "jtracer/scene.hpp"
#include "jtracer/source_map.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace jt {

// An included file an edit changes (docs/language.md §15.6): its new text,
// to be written in place like the main file's.
struct EditedFile {
    std::uint32_t file = 0;  // its first reading (SourcePos::file)
    std::string path;        // where it was read
    std::string text;        // its whole new text
    int readings = 1;        // how many times the scene reads it: each reading changes
    bool operator==(const EditedFile&) const = default;
};

struct SourceEditResult {
    std::string text;               // the new main text (the input text when nothing changed)
    std::vector<EditedFile> files;  // the included files whose text changes
    std::string error;              // non-empty when the edit cannot be expressed in place
    int values_changed = 0;
    bool ok() const { return error.empty(); }
};

// `text` parsed to `original` with the spans in `source`. `edited` may differ
// from `original` in any value, and may have more or fewer cameras at the end;
// adding or removing primitives, lights or transform operations, or changing a
// shape's kind, is reported as an error (the text is then left as it was).
SourceEditResult apply_scene_edits(std::string_view text, const SceneSource& source,
                                   const Scene& original, const Scene& edited);

}  // namespace jt
