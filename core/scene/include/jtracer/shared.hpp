#pragma once
// An immutable value held once and shared by every copy, with the copy and
// comparison of a value: copy-on-write.
//
// A million primitives mostly say the same thing about their surface; holding
// it once and a pointer a primitive keeps the scene small. Copies share the
// value; == compares values (a shared one is equal at once); edit() gives a
// value of one's own first when another copy still sees it. The count is
// atomic: scenes are copied on several threads at a time.
//
//   Shared<Finish> a;            // the default value, shared: no allocation
//   Shared<Finish> b = a;        // the same value, one more holder
//   b.edit().reflection = 0.5;   // b now holds a value of its own; a is unchanged

#include <atomic>
#include <cstddef>
#include <utility>

namespace jt {

template <class T>
class Shared {
  public:
    // The default value, one for the whole program: default-constructing
    // (the parser and the viewer make many) never allocates.
    Shared() noexcept : node_(default_node()) { node_->add(); }
    // Implicit, so that a T can be assigned wherever a Shared<T> is held.
    Shared(const T& value) : node_(new Node(value)) {}
    Shared(T&& value) : node_(new Node(std::move(value))) {}

    Shared(const Shared& other) noexcept : node_(other.node_) { node_->add(); }
    // The source is left holding the default value, never nothing: a
    // moved-from Material is still one to read.
    Shared(Shared&& other) noexcept : node_(std::exchange(other.node_, default_node())) {
        other.node_->add();
    }
    Shared& operator=(const Shared& other) noexcept {
        other.node_->add();
        Node* old = std::exchange(node_, other.node_);
        old->release();
        return *this;
    }
    Shared& operator=(Shared&& other) noexcept {
        if (this != &other) {
            Node* fallback = default_node();
            fallback->add();
            Node* old = std::exchange(node_, std::exchange(other.node_, fallback));
            old->release();
        }
        return *this;
    }
    ~Shared() { node_->release(); }

    const T& operator*() const noexcept { return node_->value; }
    const T* operator->() const noexcept { return &node_->value; }

    // The value to change: this handle's own, copied first when it is shared.
    T& edit() {
        if (!unique()) {
            Node* own = new Node(node_->value);
            std::exchange(node_, own)->release();
        }
        return node_->value;
    }

    // Whether no other handle sees this value (edit() would not copy).
    bool unique() const noexcept { return node_->count.load(std::memory_order_acquire) == 1; }
    // Whether both hold the very same value, not only an equal one.
    bool shares_with(const Shared& other) const noexcept { return node_ == other.node_; }
    // Where the value is: tells shared values apart in tests and measurements.
    const void* address() const noexcept { return &node_->value; }

    bool operator==(const Shared& other) const {
        return node_ == other.node_ || node_->value == other.node_->value;
    }

  private:
    struct Node {
        template <class... Args>
        explicit Node(Args&&... args) : value(std::forward<Args>(args)...) {}
        void add() noexcept { count.fetch_add(1, std::memory_order_relaxed); }
        void release() noexcept {
            if (count.fetch_sub(1, std::memory_order_acq_rel) == 1) delete this;
        }
        std::atomic<std::size_t> count{1};
        T value;
    };

    // Never freed (its own count keeps it above zero), so that handles in
    // static objects may outlive every other static.
    static Node* default_node() noexcept {
        static Node* const node = new Node();
        return node;
    }

    Node* node_;
};

}  // namespace jt
