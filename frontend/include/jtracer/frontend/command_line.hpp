#pragma once
// What every JTracer program's command line shares: the exit codes, the
// version flag and how a usage error is reported (the program's name, CLI11's
// message, a pointer to --help, exit 2), so that all of them behave alike.

#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace jt::frontend {

// Exit codes, as the README and the man pages document them.
enum ExitCode : int { exit_ok = 0, exit_scene_error = 1, exit_usage = 2, exit_io_error = 3 };

// Gives `handler` the signals that ask a program to stop: SIGINT, SIGTERM and
// SIGHUP (a closed terminal or a dropped ssh connection, as a farm's
// `ssh host PROGRAM ...` meets). A signal ignored on entry (nohup, a shell's
// background job) stays ignored: whoever started the process asked for that.
void handle_stop_signals(void (*handler)(int));

// From a signal handler: removes the unfinished write's temporary file
// (remove_unfinished_file), then ends the process as `signal` would have.
void end_by_signal(int signal);

// From now on the stop signals (handle_stop_signals) only ask the program to
// stop, which it polls with stop_signal() at a point where stopping leaves
// nothing half done (a render cancelled within a tile, a write finished
// first); a second one ends the process at once through end_by_signal, for
// an impatient Ctrl-C during a long write.
void catch_stop_signals();

// The signal that asked to stop (SIGINT, SIGTERM, SIGHUP), 0 while none has.
int stop_signal();

// "SIGINT", "SIGTERM", "SIGHUP" (another: "signal N").
std::string signal_name(int signal);

// Adds --version, printing "PROGRAM VERSION (REVISION)".
void add_version_flag(CLI::App& app, const std::string& program);

// Whether two paths name the same file: one existing file (also through a
// hard link, a symbolic link or another spelling), or, when either does not
// exist yet, the same place once `.`, `..` and the links of its folders are
// resolved. An output that names an input would replace it before, or
// instead of, what the user asked for (a scene overwritten by its own image,
// a reference by the render it is meant to check). A device or a pipe is no
// file's twin: it is written in place and replaces nothing.
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

// Whether `path` is a device, a pipe or a socket: written in place, with no
// folder of its own to hold a file beside it (a heat map beside /dev/null).
bool is_stream(const std::filesystem::path& path);

// Whether `path` is where standard output goes (/dev/stdout, /dev/fd/1, the
// file or pipe it is redirected to), /dev/null aside: a second document
// written there (a JUnit report after a heat map) would make one stream of
// two that no reader can part again.
bool is_standard_output(const std::filesystem::path& path);

// An output named "-" is standard output, as with most tools (`-o - | convert
// bmp:- ...`): /dev/stdout, which a pipe gets written in place and a
// redirection (`> out.bmp`) atomically, as any file. A file called "-" is
// still ./-. Any other name is returned as it is.
std::string output_name(std::string name);

// Why an image cannot be written to `output` (as output_name gives it), or
// nothing: a terminal (-o - with standard output not redirected, or a
// terminal's device) would show the image's bytes as garbage, perhaps
// changing the terminal's settings, and the image would be lost; a closed
// standard output (a job started with >&-) could only fail after the render,
// naming /dev/stdout, a file the user never named.
std::optional<std::string> output_refusal(const std::string& output);

// How messages name the output: "standard output" for -o - (/dev/stdout),
// else the name.
std::string shown_output(const std::string& output);

// A write's error message naming standard output as the user named it ("cannot
// write standard output: No space left on device"), not as /dev/stdout, a
// file the user never typed.
std::string shown_write_error(std::string message);

// Parses the command line, then runs `checks` (which may throw
// CLI::ValidationError for rules between options). Returns the exit code when
// the program should stop now: 0 after --help or --version, exit_usage after
// an error, reported on `err` as "PROGRAM: message" and a pointer to --help.
std::optional<int> parse_command_line(CLI::App& app, int argc, const char* const* argv,
                                      const std::string& program,
                                      const std::function<void()>& checks = {},
                                      std::ostream& out = std::cout, std::ostream& err = std::cerr);

}  // namespace jt::frontend
