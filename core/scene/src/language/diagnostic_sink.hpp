#pragma once
// Collects diagnostics with a cap, so that a file of garbage yields a short
// report rather than millions of lines.

#include "jtracer/diagnostics.hpp"

#include <string>
#include <vector>

namespace jt::lang {

class DiagnosticSink {
  public:
    static constexpr int max_errors = 20;
    static constexpr int max_warnings = 100;

    void error(SourcePos pos, std::string message);
    void warning(SourcePos pos, std::string message);
    // Notes count toward no limit.
    void note(SourcePos pos, std::string message);
    // False once further warnings would be dropped: skip composing them.
    bool accepts_warnings() const { return !stopped_ && warnings_ <= max_warnings; }
    // True once the error cap was reached: parsing should stop.
    bool stopped() const { return stopped_; }
    int error_count() const { return errors_; }
    // Whether anything at all was reported, notes and dropped warnings included.
    bool any() const { return errors_ > 0 || warnings_ > 0 || !diagnostics_.empty(); }
    std::vector<Diagnostic> take() { return std::move(diagnostics_); }

  private:
    std::vector<Diagnostic> diagnostics_;
    int errors_ = 0;
    int warnings_ = 0;
    bool stopped_ = false;
};

}  // namespace jt::lang
