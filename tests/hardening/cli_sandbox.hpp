#pragma once
// A scratch directory per test and jtracer-cli run inside it, either to the
// end (run) or in the background so that a test can signal it (start/finish).

#include <gtest/gtest.h>
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace jt::hardening {

struct CliResult {
    int code = -1;    // exit status, or -1 when a signal ended the process
    int signal = 0;   // the signal that ended it, 0 when it exited
    std::string err;  // everything it wrote to stderr
};

// A scene small enough to render in milliseconds, with every primitive kind.
extern const char* const small_scene;

// The showcase scene, for renders that must take a while.
std::filesystem::path showcase_path();

std::string read_file(const std::filesystem::path& path);
void write_file(const std::filesystem::path& path, const std::string& bytes);

class CliSandbox : public testing::Test {
  protected:
    std::filesystem::path dir;

    void SetUp() override;
    void TearDown() override;

    // Runs jtracer-cli in `dir` with these arguments (no shell involved).
    CliResult run(const std::vector<std::string>& args);
    // Starts it in the background; finish() waits for it.
    pid_t start(const std::vector<std::string>& args);
    // Runs it as the user 'nobody' when the tests run as root, so that file
    // permissions apply; `dir` must then be readable by others (it is).
    CliResult run_unprivileged(const std::vector<std::string>& args);
    CliResult finish(pid_t pid);

    // The names of the files in `dir`, sorted (the captured stderr excluded).
    std::vector<std::string> files() const;
    // Files whose name says they are an unfinished atomic write.
    std::vector<std::string> temporary_files() const;
};

}  // namespace jt::hardening
