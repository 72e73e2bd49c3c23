#pragma once
// jtracer-cli run in a scratch folder holding a small scene (scene.jts),
// either to the end (run) or in the background so that a test can signal it
// (start).

#include "common/files.hpp"
#include "common/run_program.hpp"
#include "common/scratch_dir.hpp"

#include <string>
#include <vector>

namespace jt::test {

// A scene small enough to render in milliseconds, with every primitive kind.
extern const char* const small_scene;

class CliSandbox : public ScratchTest {
  protected:
    void SetUp() override;

    // jtracer-cli in `dir` with these arguments (no shell involved).
    Command cli(const std::vector<std::string>& args) const;
    ProgramRun run(const std::vector<std::string>& args) const { return run_program(cli(args)); }
    // As the user 'nobody' when the tests run as root, so that file
    // permissions apply; `dir` is readable by others.
    ProgramRun run_unprivileged(const std::vector<std::string>& args) const;

    // Files whose name says they are an unfinished atomic write.
    std::vector<std::string> temporary_files() const;
};

}  // namespace jt::test
