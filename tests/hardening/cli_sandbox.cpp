#include "cli_sandbox.hpp"

#include <fcntl.h>
#include <grp.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace jt::hardening {

namespace fs = std::filesystem;

const char* const small_scene = R"(
render_settings { width: 32; height: 18; filename: "from_scene.bmp"; recurse_depth: 2; }
cameras { perspective_camera { name: "front"; position: <0, 1, 5>; look_at: <0, 0.5, 0>;
                               aspect: 1.7778; } }
scene {
    plane { material { pigment: <0.8, 0.8, 0.8>; reflection: 0.3; } }
    sphere { center: <0, 0.8, 0>; radius: 0.8; material { pigment: <1, 0.2, 0.1>; } }
    cylinder { radius: 0.3; height: 1.2; transform { translate: <1.5, 0, 0>; } }
    point_light { position: <3, 5, 4>; intensity: <1, 1, 1>; }
}
)";

fs::path showcase_path() {
    return fs::path(JT_SOURCE_DIR) / "scenes" / "showcase.jts";
}

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

void write_file(const fs::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

void CliSandbox::SetUp() {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info->name();
    std::replace(name.begin(), name.end(), '/', '_');  // parameterised tests: "Name/0"
    dir = fs::temp_directory_path() /
          ("jtracer_hardening_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    write_file(dir / "scene.jts", small_scene);
}

void CliSandbox::TearDown() {
    std::error_code ec;
    fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add, ec);
    if (!HasFailure()) fs::remove_all(dir, ec);
}

namespace {

constexpr uid_t nobody = 65534;

pid_t spawn(const fs::path& dir, const std::vector<std::string>& args, bool unprivileged) {
    // Everything the child needs is prepared before fork: after it, only
    // async-signal-safe calls.
    std::vector<std::string> strings{JT_CLI};
    strings.insert(strings.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& s : strings) argv.push_back(s.data());
    argv.push_back(nullptr);
    const std::string err_path = (dir / "stderr.txt").string();
    const std::string dir_path = dir.string();
    pid_t pid = ::fork();
    if (pid == 0) {
        int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int null = ::open("/dev/null", O_RDWR);
        if (err < 0 || null < 0 || ::chdir(dir_path.c_str()) != 0) ::_exit(126);
        if (unprivileged && ::getuid() == 0 &&
            (::setgroups(0, nullptr) != 0 || ::setgid(nobody) != 0 || ::setuid(nobody) != 0))
            ::_exit(126);
        ::dup2(null, STDIN_FILENO);
        ::dup2(null, STDOUT_FILENO);
        ::dup2(err, STDERR_FILENO);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    return pid;
}

}  // namespace

pid_t CliSandbox::start(const std::vector<std::string>& args) {
    return spawn(dir, args, false);
}

CliResult CliSandbox::run_unprivileged(const std::vector<std::string>& args) {
    return finish(spawn(dir, args, true));
}

CliResult CliSandbox::finish(pid_t pid) {
    CliResult result;
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFEXITED(status)) result.code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    result.err = read_file(dir / "stderr.txt");
    fs::remove(dir / "stderr.txt");
    return result;
}

CliResult CliSandbox::run(const std::vector<std::string>& args) {
    return finish(start(args));
}

std::vector<std::string> CliSandbox::files() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename() != "stderr.txt")
            names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::vector<std::string> CliSandbox::temporary_files() const {
    std::vector<std::string> names;
    for (const std::string& name : files())
        if (name.find(".tmp") != std::string::npos) names.push_back(name);
    return names;
}

}  // namespace jt::hardening
