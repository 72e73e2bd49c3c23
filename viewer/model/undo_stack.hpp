#pragma once
// Undo and redo as whole snapshots of what was edited (the document's text and
// scene, scene_document.hpp): simpler and safer than inverse operations.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace jt::view {

template <class Snapshot>
class SnapshotStack {
  public:
    explicit SnapshotStack(std::size_t capacity = 256) : capacity_(capacity) {}

    // Records the state as it was before an edit; clears the redo history.
    void record(Snapshot before) {
        if (!undo_.empty() && undo_.back() == before) return;  // a no-op edit
        ++changes_;
        undo_.push_back(std::move(before));
        if (undo_.size() > capacity_) undo_.erase(undo_.begin());
        redo_.clear();
    }
    // Returns the state to go back to, remembering `current` for redo.
    std::optional<Snapshot> undo(Snapshot current) {
        return step(undo_, redo_, std::move(current));
    }
    std::optional<Snapshot> redo(Snapshot current) {
        return step(redo_, undo_, std::move(current));
    }
    void clear() {
        ++changes_;
        undo_.clear();
        redo_.clear();
    }
    bool can_undo() const { return !undo_.empty(); }
    bool can_redo() const { return !redo_.empty(); }
    std::size_t size() const { return undo_.size(); }
    std::size_t capacity() const { return capacity_; }
    // Counts the records, undos, redos and clears: what was edited since a
    // moment is told by this number, whatever the capacity dropped.
    std::uint64_t changes() const { return changes_; }

  private:
    std::optional<Snapshot> step(std::vector<Snapshot>& from, std::vector<Snapshot>& to,
                                 Snapshot current) {
        if (from.empty()) return std::nullopt;
        ++changes_;
        Snapshot back = std::move(from.back());
        from.pop_back();
        to.push_back(std::move(current));
        return back;
    }

    std::size_t capacity_;
    std::uint64_t changes_ = 0;
    std::vector<Snapshot> undo_;
    std::vector<Snapshot> redo_;
};

}  // namespace jt::view
