#pragma once
// A fresh folder per test: ctest runs tests in parallel processes, so each
// folder is named after the test and the process.

#include "common/run_program.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace jt::test {

// An empty folder in the system's temporary folder, named after `label`, the
// running test and this process; emptied first if it exists. It stays.
std::filesystem::path make_scratch_dir(std::string_view label = "");

// make_scratch_dir's folder, removed at the end of the scope when the test
// has passed so far, and kept to look at when it has failed.
class ScratchDir {
  public:
    explicit ScratchDir(std::string_view label = "");
    ~ScratchDir();
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

// A test fixture with a scratch folder `dir` to run programs in.
class ScratchTest : public testing::Test {
  protected:
    ScratchDir scratch;
    const std::filesystem::path& dir = scratch.path();

    bool exists(const std::string& name) const { return std::filesystem::exists(dir / name); }
    // The names of the files in `dir`, sorted.
    std::vector<std::string> files() const;
    // `line` through /bin/sh in `dir` (see run_shell).
    ProgramRun run_shell(const std::string& line) const { return test::run_shell(line, dir); }
};

}  // namespace jt::test
