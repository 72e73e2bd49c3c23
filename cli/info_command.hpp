#pragma once
// `jtracer-cli info SCENE [--json]`: what a scene holds once loaded, for a
// user who dropped in a real model and wants to see its size and place.

namespace jt::cli {

// argv[0] is "info". Prints on stdout; exit codes as a render's: 0, 1 errors
// in the scene, 2 bad command line, 3 a file that cannot be read.
int run_info_command(int argc, char** argv);

}  // namespace jt::cli
