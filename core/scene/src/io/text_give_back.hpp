#pragma once
// Gives a large text's memory back behind a reader that goes through it once.
//
// A million spheres are 139 MB of text and 96 MB of scene: held together they
// made the peak of a render. As the parse reports the offsets it has passed
// (ParseOptions::text_passed), the whole 2 MiB pages before them are returned
// to the system (MADV_DONTNEED), so the text shrinks as the scene grows.
// A page given back reads as zeros afterwards: the text's owner must not read
// it again (load_scene_file drops it and reads the file again when a message
// needs to quote it). Off Linux it gives nothing back.

#include <cstddef>
#include <string>

namespace jt {

class TextGiveBack {
  public:
    // `text` must stay where it is while this is in use.
    explicit TextGiveBack(std::string& text);
    // Nothing before `offset` will be read again.
    void passed(std::size_t offset);
    // Whether any page was given back (the text is then no longer whole).
    bool gave_back() const { return gave_back_; }

  private:
    char* begin_;
    char* next_;  // the first byte not yet given back, on a page boundary
    bool gave_back_ = false;
};

}  // namespace jt
