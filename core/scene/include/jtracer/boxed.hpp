#pragma once
// A value kept on the heap, with the copy and comparison of the value itself.
//
// A std::variant is as large as its largest alternative, so one rare, large
// alternative (a triangle's six corners and texture coordinates) would size
// every sphere of a million-sphere scene. Boxing it keeps the variant small.

#include <memory>
#include <utility>

namespace jt {

template <class T>
class Boxed {
  public:
    Boxed() : value_(std::make_unique<T>()) {}
    // Implicit, so that a T can be assigned wherever a Boxed<T> is held.
    Boxed(const T& value) : value_(std::make_unique<T>(value)) {}
    Boxed(T&& value) : value_(std::make_unique<T>(std::move(value))) {}

    Boxed(const Boxed& other) : value_(std::make_unique<T>(*other.value_)) {}
    Boxed& operator=(const Boxed& other) {
        if (this != &other) value_ = std::make_unique<T>(*other.value_);
        return *this;
    }
    // Moving leaves the source empty (only destroying or assigning to it is
    // allowed then); it must not allocate, so that vectors of boxes move
    // rather than copy when they grow.
    Boxed(Boxed&&) noexcept = default;
    Boxed& operator=(Boxed&&) noexcept = default;

    T& get() { return *value_; }
    constexpr const T& get() const { return *value_; }
    T& operator*() { return *value_; }
    const T& operator*() const { return *value_; }
    T* operator->() { return value_.get(); }
    const T* operator->() const { return value_.get(); }

    bool operator==(const Boxed& other) const { return *value_ == *other.value_; }

  private:
    std::unique_ptr<T> value_;
};

}  // namespace jt
