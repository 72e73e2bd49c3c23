#include "undo_stack.hpp"

namespace jt::view {

void UndoStack::record(const Scene& before) {
    if (!undo_.empty() && undo_.back() == before) return;  // a no-op edit
    undo_.push_back(before);
    if (undo_.size() > capacity_) undo_.erase(undo_.begin());
    redo_.clear();
}

std::optional<Scene> UndoStack::undo(const Scene& current) {
    if (undo_.empty()) return std::nullopt;
    Scene previous = std::move(undo_.back());
    undo_.pop_back();
    redo_.push_back(current);
    return previous;
}

std::optional<Scene> UndoStack::redo(const Scene& current) {
    if (redo_.empty()) return std::nullopt;
    Scene next = std::move(redo_.back());
    redo_.pop_back();
    undo_.push_back(current);
    return next;
}

void UndoStack::clear() {
    undo_.clear();
    redo_.clear();
}

}  // namespace jt::view
