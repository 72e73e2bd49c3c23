#include "jtracer/source_files.hpp"

namespace jt {

std::string_view file_text(std::span<const SourceFile> files, std::string_view main_text,
                           std::uint32_t file) {
    if (file == 0) return main_text;
    return file <= files.size() ? std::string_view(files[file - 1].text) : std::string_view();
}

std::string_view file_name(std::span<const SourceFile> files, std::string_view main_name,
                           std::uint32_t file) {
    if (file == 0 || file > files.size()) return main_name;
    return files[file - 1].name;
}

std::string format_diagnostic(const Diagnostic& diagnostic, std::string_view main_name,
                              std::string_view main_text, std::span<const SourceFile> files) {
    const std::uint32_t file = diagnostic.pos.file;
    std::string out = format_diagnostic(diagnostic, file_name(files, main_name, file),
                                        file_text(files, main_text, file));
    // Innermost first; each step is to an earlier file, so this ends.
    for (std::uint32_t k = file; k > 0 && k <= files.size();) {
        const SourcePos at = files[k - 1].included_at;
        out += "note: included from " + std::string(file_name(files, main_name, at.file)) + ":" +
               std::to_string(at.line) + ":" + std::to_string(at.column) + "\n";
        k = at.file;
    }
    return out;
}

}  // namespace jt
