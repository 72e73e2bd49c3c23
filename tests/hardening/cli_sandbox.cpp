#include "cli_sandbox.hpp"

namespace jt::test {

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

void CliSandbox::SetUp() {
    write_file(dir / "scene.jts", small_scene);
}

Command CliSandbox::cli(const std::vector<std::string>& args) const {
    Command command{{JT_CLI}, dir};
    command.argv.insert(command.argv.end(), args.begin(), args.end());
    return command;
}

ProgramRun CliSandbox::run_unprivileged(const std::vector<std::string>& args) const {
    Command command = cli(args);
    command.unprivileged = true;
    return run_program(command);
}

std::vector<std::string> CliSandbox::temporary_files() const {
    std::vector<std::string> names;
    for (const std::string& name : files())
        if (name.find(".tmp") != std::string::npos) names.push_back(name);
    return names;
}

}  // namespace jt::test
