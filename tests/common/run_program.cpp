#include "common/run_program.hpp"

#include "common/files.hpp"

#include <fcntl.h>
#include <grp.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>

namespace jt::test {

namespace fs = std::filesystem;

namespace {

constexpr uid_t kNobody = 65534;

// A new empty file in the temporary folder, for one stream of one run.
fs::path capture_file(const char* stream) {
    std::string name = (fs::temp_directory_path() / "jtracer-run-").string() + stream + "-XXXXXX";
    int fd = ::mkstemp(name.data());
    if (fd >= 0) ::close(fd);
    return name;
}

}  // namespace

RunningProgram::RunningProgram(const Command& command)
    : out_path_(capture_file("out")), err_path_(capture_file("err")) {
    // Everything the child needs is prepared before fork: after it, only
    // async-signal-safe calls.
    std::vector<std::string> strings = command.argv;
    std::vector<char*> argv;
    for (std::string& s : strings) argv.push_back(s.data());
    argv.push_back(nullptr);
    const std::string out_path = out_path_.string();
    const std::string err_path = err_path_.string();
    const std::string cwd = command.cwd.string();
    const bool unprivileged = command.unprivileged && ::getuid() == 0;
    if (strings.empty()) return;
    pid_ = ::fork();
    if (pid_ == 0) {
        int out = ::open(out_path.c_str(), O_WRONLY | O_TRUNC);
        int err = ::open(err_path.c_str(), O_WRONLY | O_TRUNC);
        int null = ::open("/dev/null", O_RDONLY);
        if (out < 0 || err < 0 || null < 0 || (!cwd.empty() && ::chdir(cwd.c_str()) != 0))
            ::_exit(126);
        if (unprivileged &&
            (::setgroups(0, nullptr) != 0 || ::setgid(kNobody) != 0 || ::setuid(kNobody) != 0))
            ::_exit(126);
        ::dup2(null, STDIN_FILENO);
        ::dup2(out, STDOUT_FILENO);
        ::dup2(err, STDERR_FILENO);
        ::execvp(argv[0], argv.data());
        ::_exit(127);
    }
}

RunningProgram::~RunningProgram() {
    if (pid_ > 0) {
        ::kill(pid_, SIGKILL);
        finish();
    }
    std::error_code ec;
    fs::remove(out_path_, ec);
    fs::remove(err_path_, ec);
}

std::string RunningProgram::err_so_far() const {
    return read_file(err_path_);
}

ProgramRun RunningProgram::finish() {
    ProgramRun run;
    if (pid_ <= 0) return run;
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    if (WIFEXITED(status)) run.code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) run.signal = WTERMSIG(status);
    run.out = read_file(out_path_);
    run.err = read_file(err_path_);
    return run;
}

ProgramRun run_program(const Command& command) {
    return RunningProgram(command).finish();
}

ProgramRun run_shell(const std::string& line, const fs::path& cwd) {
    return run_program({{"/bin/sh", "-c", line}, cwd});
}

}  // namespace jt::test
