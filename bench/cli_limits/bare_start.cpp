// gyrores-bare-start: a program that does nothing, linked with the libraries and link options of
// the gyrores CLI (bench/CMakeLists.txt; bench/cli_overhead.py checks that its dynamic
// dependencies are the CLI's). The start-up floor `gyrores pair 6 5` is measured against: the
// loader mapping and relocating the same shared libraries and running their initialisers.
int main() { return 0; }
