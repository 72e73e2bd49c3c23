#include "jtracer/diagnostics.hpp"

#include <gtest/gtest.h>

namespace jt {
namespace {

TEST(FormatDiagnostic, QuotesTheLineWithACaretUnderTheColumn) {
    Diagnostic d{Severity::error, {2, 13}, "expected ';' after the value of 'radius'"};
    std::string text = "sphere {\n    radius: 2\n}\n";
    EXPECT_EQ(format_diagnostic(d, "a.jts", text),
              "a.jts:2:13: error: expected ';' after the value of 'radius'\n"
              "        radius: 2\n"
              "                ^\n");
}

TEST(FormatDiagnostic, WarningWithoutLocationHasNoQuote) {
    Diagnostic d{Severity::warning, {}, "no scene block"};
    EXPECT_EQ(format_diagnostic(d, "a.jts", "x"), "a.jts: warning: no scene block\n");
}

TEST(HasErrors, IgnoresWarnings) {
    std::vector<Diagnostic> ds{{Severity::warning, {1, 1}, "w"}};
    EXPECT_FALSE(has_errors(ds));
    ds.push_back({Severity::error, {1, 1}, "e"});
    EXPECT_TRUE(has_errors(ds));
}

}  // namespace
}  // namespace jt

namespace jt {
namespace {

TEST(FormatDiagnostic, LongLinesAreQuotedAsAWindowAroundTheColumn) {
    std::string text = std::string(1000000, ' ') + "oops" + std::string(1000000, ' ');
    Diagnostic d{Severity::error, {1, 1000001}, "bad"};
    std::string out = format_diagnostic(d, "a.jts", text);
    std::string quote = "    ..." + std::string(80, ' ') + "oops" + std::string(116, ' ') + "...\n";
    std::string caret = "    " + std::string(83, ' ') + "^\n";
    EXPECT_EQ(out, "a.jts:1:1000001: error: bad\n" + quote + caret);
}

TEST(FormatDiagnostic, CaretPastTheEndOfTheLineSitsJustAfterIt) {
    Diagnostic d{Severity::error, {1, 5}, "expected ';'"};
    EXPECT_EQ(format_diagnostic(d, "a.jts", "a: 1\n"),
              "a.jts:1:5: error: expected ';'\n    a: 1\n        ^\n");
}

TEST(FormatDiagnostic, ControlBytesAndTabsKeepTheCaretAligned) {
    Diagnostic d{Severity::error, {1, 4}, "x"};
    EXPECT_EQ(format_diagnostic(d, "f", "\t\x01\xC3x"), "f:1:4: error: x\n     ??x\n       ^\n");
}

}  // namespace
}  // namespace jt
