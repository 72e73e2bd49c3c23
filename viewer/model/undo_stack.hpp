#pragma once
// Undo and redo of scene edits, as whole-scene snapshots: a Scene is a small
// value, so a snapshot is simpler and safer than inverse operations.

#include "jtracer/scene.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace jt::view {

class UndoStack {
  public:
    explicit UndoStack(std::size_t capacity = 256) : capacity_(capacity) {}

    // Records the scene as it was before an edit; clears the redo history.
    void record(const Scene& before);
    // Returns the scene to go back to, remembering `current` for redo.
    std::optional<Scene> undo(const Scene& current);
    std::optional<Scene> redo(const Scene& current);
    void clear();
    bool can_undo() const { return !undo_.empty(); }
    bool can_redo() const { return !redo_.empty(); }
    std::size_t size() const { return undo_.size(); }

  private:
    std::size_t capacity_;
    std::vector<Scene> undo_;
    std::vector<Scene> redo_;
};

}  // namespace jt::view
