// Empty on purpose: CMake builds a target's precompiled headers only for a target with a source
// that uses them, and catch_main.cpp cannot (tests/CMakeLists.txt). The tests reuse them.
