#include "language/diagnostic_sink.hpp"

namespace jt::lang {

void DiagnosticSink::error(SourcePos pos, std::string message) {
    if (stopped_) return;
    if (errors_ == max_errors) {
        diagnostics_.push_back(
            {Severity::error, pos,
             "too many errors (" + std::to_string(max_errors) + "); stopping here"});
        stopped_ = true;
        return;
    }
    ++errors_;
    diagnostics_.push_back({Severity::error, pos, std::move(message)});
}

void DiagnosticSink::warning(SourcePos pos, std::string message) {
    if (stopped_ || warnings_ > max_warnings) return;
    if (warnings_++ == max_warnings) {
        diagnostics_.push_back(
            {Severity::warning, pos, "too many warnings; the rest are not shown"});
        return;
    }
    diagnostics_.push_back({Severity::warning, pos, std::move(message)});
}

void DiagnosticSink::note(SourcePos pos, std::string message) {
    if (stopped_) return;
    diagnostics_.push_back({Severity::note, pos, std::move(message)});
}

}  // namespace jt::lang
