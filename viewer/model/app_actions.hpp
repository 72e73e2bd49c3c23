#pragma once
// The viewer's commands, each a free function, shared by the panels, the
// keyboard shortcuts and the tests. A command takes the parts of AppState it
// changes (const the parts it only reads); one that takes the whole state
// changes several and leaves a one-line outcome in state.message.

#include "model/camera_commands.hpp"
#include "model/edit_commands.hpp"
#include "model/file_commands.hpp"
#include "model/render_commands.hpp"
