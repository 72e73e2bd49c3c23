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
