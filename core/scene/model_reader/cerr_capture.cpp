#include "model_reader/cerr_capture.hpp"

#include <algorithm>
#include <iostream>
#include <mutex>
#include <sstream>
#include <streambuf>
#include <vector>

namespace jt {

namespace {

// Where this thread's std::cerr text goes while it captures; null otherwise.
thread_local std::string* capturing = nullptr;

// Unbuffered, so that each write is decided by the thread that makes it.
class PerThreadBuffer : public std::streambuf {
  public:
    explicit PerThreadBuffer(std::streambuf* passed_to) : passed_to_(passed_to) {}

  protected:
    std::streamsize xsputn(const char* text, std::streamsize n) override {
        if (capturing) {
            capturing->append(text, static_cast<std::size_t>(n));
            return n;
        }
        return passed_to_ ? passed_to_->sputn(text, n) : n;
    }
    int_type overflow(int_type c) override {
        if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
        const char one = traits_type::to_char_type(c);
        return xsputn(&one, 1) == 1 ? c : traits_type::eof();
    }
    int sync() override {
        if (capturing || !passed_to_) return 0;
        return passed_to_->pubsync();
    }

  private:
    std::streambuf* passed_to_;
};

// Put in front of std::cerr's buffer unless it is already there: once in a
// process, again only if a program put a buffer of its own in its place since.
void install() {
    static std::mutex lock;
    const std::lock_guard<std::mutex> hold(lock);
    if (dynamic_cast<PerThreadBuffer*>(std::cerr.rdbuf())) return;
    std::cerr.flush();
    // Never deleted: std::cerr may write to it until the process ends. Also
    // held here, where the leak checker finds it reachable (std::cerr's own
    // pointer to it is not one it scans).
    static auto* const installed = new std::vector<PerThreadBuffer*>();
    installed->push_back(new PerThreadBuffer(std::cerr.rdbuf()));
    std::cerr.rdbuf(installed->back());
}

}  // namespace

CerrCapture::CerrCapture() {
    install();
    outer_ = capturing;
    capturing = &caught_;
}

CerrCapture::~CerrCapture() {
    capturing = outer_;
}

std::vector<std::pair<std::string, std::size_t>> CerrCapture::lines() const {
    std::vector<std::pair<std::string, std::size_t>> out;
    std::istringstream text(caught_);
    std::string line;
    while (std::getline(text, line)) {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        if (line.empty()) continue;
        const auto seen = std::find_if(out.begin(), out.end(),
                                       [&](const auto& said) { return said.first == line; });
        if (seen != out.end())
            ++seen->second;
        else
            out.emplace_back(line, 1);
    }
    return out;
}

}  // namespace jt
