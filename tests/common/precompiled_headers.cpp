// Compiles the tests' precompiled header (tests/CMakeLists.txt), which every
// test program reuses; nothing else lives here.
