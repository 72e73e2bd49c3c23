#pragma once
// Running one of the programs from a test, in a scratch folder of its own.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace jt::test {

struct CommandRun {
    int code = -1;    // the exit code, -1 if it did not exit normally
    std::string err;  // what it wrote to stderr
};

inline std::string file_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// A fresh folder per test and process, removed when the test passes.
class ScratchDir : public testing::Test {
  protected:
    std::filesystem::path dir;

    void SetUp() override {
        const auto* info = testing::UnitTest::GetInstance()->current_test_info();
        dir = std::filesystem::temp_directory_path() /
              ("jtracer_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
               std::to_string(::getpid()));
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
    }
    void TearDown() override {
        if (!HasFailure()) std::filesystem::remove_all(dir);
    }

    // Runs `command` (a shell command line) in `dir` with stderr captured.
    CommandRun run(const std::string& command) {
        std::string line = "cd '";
        line.append(dir.string()).append("' && ").append(command);
        line.append(" > stdout.txt 2> stderr.txt");
        int status = std::system(line.c_str());
        CommandRun r;
        r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        r.err = file_text(dir / "stderr.txt");
        return r;
    }

    bool exists(const std::string& name) const { return std::filesystem::exists(dir / name); }
};

}  // namespace jt::test
