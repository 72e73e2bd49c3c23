#include "jtracer/frontend/command_line.hpp"

#include "jtracer/version.hpp"

#include <CLI/CLI.hpp>

namespace jt::frontend {

void add_version_flag(CLI::App& app, const std::string& program) {
    app.set_version_flag("--version", program + " " + jt::version_string());
}

std::optional<int> parse_command_line(CLI::App& app, int argc, const char* const* argv,
                                      const std::string& program,
                                      const std::function<void()>& checks, std::ostream& out,
                                      std::ostream& err) {
    try {
        app.parse(argc, argv);
        if (checks) checks();
        return std::nullopt;
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e, out, err);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e, out, err);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e, out, err);
    } catch (const CLI::ParseError& e) {
        // CLI11's own exit codes (105, 109, ...) mean nothing to a user's script.
        err << program << ": " << e.what() << "\nRun '" << program << " --help' for the options.\n";
        return exit_usage;
    }
}

}  // namespace jt::frontend
