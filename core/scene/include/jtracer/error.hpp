#pragma once
// The one way everything outside the scene language reports a failure (file
// I/O, image codecs, regions, preparing a scene, setting up a render): the
// function returns an Expected<T>, which holds either its value or an Error
// saying what failed and why, in words for the user ("cannot write
// 'out/x.bmp': No such file or directory"). Nothing in the core's public API
// throws; only running out of memory still raises std::bad_alloc, as in the
// standard library.
//
// The scene language reports through diagnostics instead (diagnostics.hpp):
// one file can hold many mistakes, each with its own location.
//
// The interface is the part of C++23's std::expected the project uses, so that
// the standard one can replace it once the project moves on:
//
//   jt::Expected<jt::Image8> image = jt::read_image(path);
//   if (!image) { report(image.error().message); return; }
//   use(*image);
//
//   jt::Expected<void> written = jt::write_image(path, *image, format);
//   if (!written) report(written.error().message);
//
// A function builds a failure as `return jt::Error{"message"};`.

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace jt {

struct Error {
    std::string message;
};

template <class T>
class [[nodiscard]] Expected {
  public:
    Expected(T value) : held_(std::in_place_index<0>, std::move(value)) {}
    Expected(Error error) : held_(std::in_place_index<1>, std::move(error)) {}

    bool has_value() const { return held_.index() == 0; }
    explicit operator bool() const { return has_value(); }

    T& value() & { return *std::get_if<0>(&checked_value()); }
    const T& value() const& { return *std::get_if<0>(&checked_value()); }
    T&& value() && { return std::move(*std::get_if<0>(&checked_value())); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }
    T&& operator*() && { return std::move(*this).value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }

    // Only on failure.
    const Error& error() const {
        if (has_value()) misused("error() of a call that succeeded");
        return *std::get_if<1>(&held_);
    }

  private:
    std::variant<T, Error> held_;

    // Reading the side that is not there is a bug in the caller: it stops the
    // program with the error it skipped, rather than throwing.
    std::variant<T, Error>& checked_value() {
        if (!has_value()) misused(std::get_if<1>(&held_)->message);
        return held_;
    }
    const std::variant<T, Error>& checked_value() const {
        if (!has_value()) misused(std::get_if<1>(&held_)->message);
        return held_;
    }
    [[noreturn]] static void misused(const std::string& what) {
        std::fprintf(stderr, "jt::Expected read on the wrong side: %s\n", what.c_str());
        std::abort();
    }
};

// A function that has nothing to return but whether it worked.
template <>
class [[nodiscard]] Expected<void> {
  public:
    Expected() = default;
    Expected(Error error) : error_(std::move(error)) {}

    bool has_value() const { return !error_; }
    explicit operator bool() const { return has_value(); }

    // Only on failure.
    const Error& error() const {
        if (!error_) {
            std::fprintf(stderr,
                         "jt::Expected read on the wrong side: error() of a call that "
                         "succeeded\n");
            std::abort();
        }
        return *error_;
    }

  private:
    std::optional<Error> error_;
};

}  // namespace jt
