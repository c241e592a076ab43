// Writing a file atomically: the text goes to FILE.tmp.<pid> in the same directory and is
// renamed over FILE only when complete, so no half-written FILE is ever on disk.
#pragma once
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include <gyrores/error.hpp>

namespace gyrores::cli {

inline void write_file_atomically(const std::string& path, const std::string& text) {
  std::string tmp = path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw usage_error("cannot write '" + path + "'");
    out << text;
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw usage_error("cannot write '" + path + "'");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw usage_error("cannot write '" + path + "'");
  }
}

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw usage_error("cannot read '" + path + "'");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace gyrores::cli
