#pragma once
// What Assimp writes to std::cerr while it reads a file, caught and handed to
// the caller instead: its OpenGEX reader (openddlparser) prints lines such as
// "nullptr returned by creating DDLNode." there itself, which on the terminal
// named no file. read_model reports them as warnings of the model
// (ModelLeftOut::reader_said).
//
// std::cerr is the process's, and other threads (the viewer's) write to it
// while a model is read: so its buffer is replaced once, for good, by one
// that catches what the capturing thread writes and passes every other
// thread's text on to the buffer it replaced, untouched. Nothing is swapped
// back and forth under another thread's feet. (The module is never unloaded,
// so the buffer outlives every use of std::cerr.) A program that puts a
// buffer of its own on std::cerr later gets it wrapped at the next capture.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace jt {

// Catches this thread's std::cerr text for its lifetime.
class CerrCapture {
  public:
    CerrCapture();
    ~CerrCapture();
    CerrCapture(const CerrCapture&) = delete;
    CerrCapture& operator=(const CerrCapture&) = delete;

    // The lines caught so far, each once in the order first seen, with how
    // often it came; blank lines left out.
    std::vector<std::pair<std::string, std::size_t>> lines() const;

  private:
    std::string caught_;
    std::string* outer_ = nullptr;  // a capture this one is inside, if any
};

}  // namespace jt
