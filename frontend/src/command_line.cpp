#include "jtracer/frontend/command_line.hpp"

#include "jtracer/atomic_file.hpp"
#include "jtracer/version.hpp"

#include <CLI/CLI.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <csignal>
#include <cstdlib>
#include <memory>

namespace jt::frontend {

namespace {

std::atomic<int> caught_signal{0};

extern "C" void on_stop_signal(int signal) {
    if (caught_signal.exchange(signal) != 0) end_by_signal(signal);
}

// --help as GNU tools print it: "Usage: jtracer-cli [OPTIONS] SCENE" with the
// program's name (not the path it was started from), operands in capitals,
// and each option followed by the word for its value ("--width N") rather
// than CLI11's type and validator ("INT:INT in [1 - 65535]", or a
// transformer's whole mapping); the ranges and choices are in the option's
// description.
class GnuHelp : public CLI::Formatter {
  public:
    GnuHelp() { label("Positionals", "Arguments"); }

    std::string make_option_name(const CLI::Option* opt, bool positional) const override {
        if (!positional) return CLI::Formatter::make_option_name(opt, positional);
        std::string name = opt->get_name(true, false);
        for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        return name;
    }

    std::string make_option_opts(const CLI::Option* opt) const override {
        if (opt->get_positional() || opt->get_type_size() == 0) return {};
        if (!opt->get_option_text().empty()) return " " + opt->get_option_text();
        const std::string type = opt->get_type_name();
        std::string opts = " " + type.substr(0, type.find(':'));
        if (!opt->get_default_str().empty()) opts += "=" + opt->get_default_str();
        return opts;
    }
};

// An option as messages name it: "-o/--output", or a positional's name in
// capitals ("PARTS"), as --help shows it.
std::string shown_name(const CLI::Option& opt) {
    if (opt.get_positional()) return GnuHelp().make_option_name(&opt, true);
    std::string name = opt.get_name(false, true);
    for (char& c : name)
        if (c == ',') c = '/';
    return name;
}

// The word for an option's value ("FILE", "N"), as --help shows it.
std::string value_word(const CLI::Option& opt) {
    if (!opt.get_option_text().empty()) return opt.get_option_text();
    const std::string type = opt.get_type_name();
    return type.substr(0, type.find(':'));
}

// The first word of the command line that looks like an option and is none
// of the program's ("--bogus", "-Z" of "-Zq"), or nothing. CLI11 checks
// required options before unknown ones, so a mistyped option would otherwise
// be reported as a missing one.
std::optional<std::string> unknown_option(const CLI::App& app, int argc, const char* const* argv) {
    if (app.get_allow_extras()) return std::nullopt;
    for (int i = 1; i < argc; ++i) {
        const std::string word = argv[i];
        if (word == "--") break;
        std::string name;
        if (word.size() > 2 && word.starts_with("--"))
            name = word.substr(0, word.find('='));
        else if (word.size() > 1 && word[0] == '-' && word[1] != '-' &&
                 !std::isdigit(static_cast<unsigned char>(word[1])) && word[1] != '.')
            name = word.substr(0, 2);
        if (!name.empty() && app.get_option_no_throw(name) == nullptr) return name;
    }
    return std::nullopt;
}

// The option a CLI11 message starts with ("--frames: Value ..."), if any.
const CLI::Option* named_option(const CLI::App& app, const std::string& message) {
    const std::size_t colon = message.find(": ");
    if (colon == std::string::npos) return nullptr;
    return app.get_option_no_throw(message.substr(0, colon));
}

// Whether the option's first check is a CLI::Range of integers ("INT in [1 -
// 1000000]"), which says "not in range" of "2.5" too.
bool integer_range(const CLI::Option& opt) {
    try {
        const std::string description =
            const_cast<CLI::Option&>(opt).get_validator()->get_description();
        return description.starts_with("INT") || description.starts_with("UINT");
    } catch (const CLI::OptionNotFound&) {
        return false;
    }
}

bool whole_number(const std::string& text) {
    std::size_t at = text.starts_with('-') || text.starts_with('+') ? 1 : 0;
    if (at == text.size()) return false;
    for (; at < text.size(); ++at)
        if (!std::isdigit(static_cast<unsigned char>(text[at]))) return false;
    return true;
}

// A usage error in the programs' own words: the option named as --help names
// it, what it expects, instead of CLI11's ("--output is required", "At Most 1
// required but received 2", "Value 2.5 not in range 1 to 1000000").
std::string usage_message(const CLI::App& app, const CLI::ParseError& error, int argc,
                          const char* const* argv) {
    if (std::optional<std::string> unknown = unknown_option(app, argc, argv))
        return "unknown option '" + *unknown + "'";
    const std::string message = error.what();
    if (dynamic_cast<const CLI::RequiredError*>(&error) != nullptr) {
        for (const CLI::Option* opt : app.get_options()) {
            if (!opt->get_required() || opt->count() != 0) continue;
            if (opt->get_positional()) return "missing " + shown_name(*opt);
            return "missing " + shown_name(*opt) + " " + value_word(*opt);
        }
        return message;
    }
    if (dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr) {
        const std::size_t colon = message.find(": ");
        return "unexpected argument" +
               (colon == std::string::npos ? "" : ": " + message.substr(colon + 2));
    }
    const CLI::Option* opt = named_option(app, message);
    if (opt == nullptr) return message;
    const std::string name = shown_name(*opt);
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) != nullptr) {
        if (message.find("At Most") != std::string::npos)
            return name + ": given more than once; give it once";
        return name + ": needs " + value_word(*opt) + " after it";
    }
    static constexpr std::string_view range_words = "Value ";
    const std::size_t value_at = message.find(range_words);
    const std::size_t range_at = message.find(" not in range ");
    if (dynamic_cast<const CLI::ValidationError*>(&error) != nullptr &&
        value_at != std::string::npos && range_at != std::string::npos && range_at > value_at) {
        const std::string value =
            message.substr(value_at + range_words.size(), range_at - value_at - range_words.size());
        const std::string range =
            message.substr(range_at + std::string_view(" not in range ").size());
        const bool integer = integer_range(*opt);
        if (integer && !whole_number(value))
            return name + ": '" + value + "' is not a whole number (expected " + range + ")";
        char* end = nullptr;
        (void)std::strtod(value.c_str(), &end);
        if (value.empty() || end != value.c_str() + value.size())
            return name + ": '" + value + "' is not a number (expected " + range + ")";
        return name + ": " + value + " is out of range (expected " + range + ")";
    }
    return message;
}

}  // namespace

std::string output_name(std::string name) {
    return name == "-" ? std::string("/dev/stdout") : name;
}

bool is_stream(const std::filesystem::path& path) {
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    return std::filesystem::is_character_file(status) || std::filesystem::is_fifo(status) ||
           std::filesystem::is_block_file(status) || std::filesystem::is_socket(status);
}

bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
    // A device or pipe is written in place (atomic_file.cpp): /dev/null as
    // both the image and the report replaces nothing.
    if (is_stream(a) || is_stream(b)) return false;
    std::error_code error;
    if (std::filesystem::equivalent(a, b, error)) return true;
    const std::filesystem::path place_a = std::filesystem::weakly_canonical(a, error);
    if (error) return false;
    const std::filesystem::path place_b = std::filesystem::weakly_canonical(b, error);
    return !error && place_a == place_b;
}

bool is_standard_output(const std::filesystem::path& path) {
    struct stat named {};
    struct stat out {};
    if (::stat(path.c_str(), &named) != 0 || ::fstat(STDOUT_FILENO, &out) != 0) return false;
    if (named.st_dev != out.st_dev || named.st_ino != out.st_ino) return false;
    // Whatever reaches /dev/null is gone: nothing there to mix.
    struct stat null {};
    return !(S_ISCHR(named.st_mode) && ::stat("/dev/null", &null) == 0 &&
             named.st_rdev == null.st_rdev);
}

std::optional<std::string> output_refusal(const std::string& output) {
    bool terminal = false;
    if (output == "/dev/stdout" && ::fcntl(STDOUT_FILENO, F_GETFD) < 0)
        return std::string(
            "standard output is closed: redirect it to a file or a pipe, or name "
            "a file");
    if (output == "/dev/stdout") {
        terminal = ::isatty(STDOUT_FILENO) != 0;
    } else {
        std::error_code error;
        if (std::filesystem::is_character_file(output, error)) {
            // Opened without becoming the process's terminal, and without
            // waiting on a device that is not ready.
            const int descriptor = ::open(output.c_str(), O_WRONLY | O_NOCTTY | O_NONBLOCK);
            if (descriptor >= 0) {
                terminal = ::isatty(descriptor) != 0;
                ::close(descriptor);
            }
        }
    }
    if (!terminal) return std::nullopt;
    return (output == "/dev/stdout" ? std::string("standard output") : "'" + output + "'") +
           " is a terminal, where an image's bytes would show as garbage and be lost: "
           "redirect standard output to a file or a pipe (-o - > shot.bmp, -o - | ...), or "
           "name a file";
}

std::string shown_output(const std::string& output) {
    return output == "/dev/stdout" ? std::string("standard output") : output;
}

std::string shown_write_error(std::string message) {
    static constexpr std::string_view named = "'/dev/stdout'";
    if (const std::size_t at = message.find(named); at != std::string::npos)
        message.replace(at, named.size(), "standard output");
    return message;
}

void handle_stop_signals(void (*handler)(int)) {
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction current {};
        if (::sigaction(signal, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue;
        std::signal(signal, handler);
    }
}

void end_by_signal(int signal) {
    remove_unfinished_file();
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

void catch_stop_signals() {
    handle_stop_signals(on_stop_signal);
}

int stop_signal() {
    return caught_signal.load();
}

std::string signal_name(int signal) {
    switch (signal) {
        case SIGINT:
            return "SIGINT";
        case SIGTERM:
            return "SIGTERM";
        case SIGHUP:
            return "SIGHUP";
        default:
            return "signal " + std::to_string(signal);
    }
}

void add_version_flag(CLI::App& app, const std::string& program) {
    app.set_version_flag("--version", program + " " + jt::version_string());
}

std::optional<int> parse_command_line(CLI::App& app, int argc, const char* const* argv,
                                      const std::string& program,
                                      const std::function<void()>& checks, std::ostream& out,
                                      std::ostream& err) {
    if (app.get_name().empty()) app.name(program);
    app.formatter(std::make_shared<GnuHelp>());
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
        err << program << ": " << usage_message(app, e, argc, argv) << "\nRun '" << program
            << " --help' for the options.\n";
        return exit_usage;
    }
}

}  // namespace jt::frontend
