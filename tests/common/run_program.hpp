#pragma once
// Running one of the programs from a test, with its output captured. No shell
// is involved unless the test asks for one (run_shell).

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace jt::test {

struct Command {
    std::vector<std::string> argv;  // argv[0]: a path, or a name looked up in PATH
    std::filesystem::path cwd;      // where it runs; empty: the test's own folder
    // Run as the user 'nobody' when the tests run as root, so that file
    // permissions apply; `cwd` must then be readable by others.
    bool unprivileged = false;
};

struct ProgramRun {
    int code = -1;    // exit status, or -1 when a signal ended the process
    int signal = 0;   // the signal that ended it, 0 when it exited
    std::string out;  // everything it wrote to stdout
    std::string err;  // everything it wrote to stderr
};

// A program started in the background, so that a test can watch or signal it.
// Its output goes to files outside `cwd`, so it never shows among the files
// the program wrote. One that is never finished is killed at destruction.
class RunningProgram {
  public:
    explicit RunningProgram(const Command& command);
    ~RunningProgram();
    RunningProgram(const RunningProgram&) = delete;
    RunningProgram& operator=(const RunningProgram&) = delete;

    pid_t pid() const { return pid_; }  // > 0 once started
    std::string err_so_far() const;
    ProgramRun finish();  // waits for it to end

  private:
    pid_t pid_ = -1;
    std::filesystem::path out_path_, err_path_;
};

ProgramRun run_program(const Command& command);

// `line` through /bin/sh, for tests that need redirections, variables or
// `timeout`; quote each path in it.
ProgramRun run_shell(const std::string& line, const std::filesystem::path& cwd = {});

}  // namespace jt::test
