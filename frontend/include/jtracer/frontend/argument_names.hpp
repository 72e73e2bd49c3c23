#pragma once
// How a renderer's messages name what its user sets beside the scene file: a
// size, a camera, a region, the defines and the clock. The rules and their
// messages are written once (the core, frame_setup, memory_budget); each front
// end gives its own words for them: jtracer-cli's and jtracer-mpi's flags by
// default, the Python module's arguments (python/src/bindings.hpp).

#include "jtracer/parser.hpp"

#include <string>
#include <string_view>

namespace jt::frontend {

struct ArgumentNames {
    ValueNames values = {"--define", "--define ", "", "--clock"};
    // Before a setting's name: "--" for "--width".
    std::string_view prefix = "--";
    // After "or pass NAME" in a diagnostic that asks for a setting.
    std::string_view after_pass = "";

    // "--width", "--camera", "--region".
    std::string name(std::string_view setting) const {
        std::string text(prefix);
        text.append(setting);
        return text;
    }
};

}  // namespace jt::frontend
