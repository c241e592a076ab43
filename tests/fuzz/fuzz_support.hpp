// Helpers shared by the libFuzzer targets of tests/fuzz/ (docs/testing.md): splitting one input
// into several strings, and a private scratch directory for the targets that read files.
//
// What a target may throw: usage_error (bad input, exit 2 in the CLI) and compute_error. Any
// other exception escapes LLVMFuzzerTestOneInput, which libFuzzer reports as a crash: the CLI
// would print "internal error" for it, which bad input must never cause.
#pragma once
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace gyrores::fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return std::string_view(reinterpret_cast<const char*>(data), size);
}

// The body of a checker's target: an input up to max_size bytes gets a verdict from `check`
// (0, 1 or 2 and a one-line message), never a crash or an exception; a longer one is skipped.
template <class Check> int checker_verdict(const std::uint8_t* data, std::size_t size, std::size_t max_size, Check check) {
  if (size > max_size) return -1;
  const auto v = check(std::string(as_text(data, size)));
  if (v.status < 0 || v.status > 2 || v.message.empty() || v.message.find('\n') != std::string::npos) std::abort();
  return 0;
}

// The pieces of `text` between occurrences of `sep`, at most `max_parts` (the last keeps the rest).
inline std::vector<std::string> split(std::string_view text, std::string_view sep, std::size_t max_parts) {
  std::vector<std::string> parts;
  while (parts.size() + 1 < max_parts) {
    const auto at = text.find(sep);
    if (at == std::string_view::npos) break;
    parts.emplace_back(text.substr(0, at));
    text.remove_prefix(at + sep.size());
  }
  parts.emplace_back(text);
  return parts;
}

// The separator of the files inside one input of the file-reading targets: two ASCII record
// separators (0x1e), which no text file of gyrores contains.
inline constexpr std::string_view file_separator = "\x1e\x1e";

// A scratch directory made once per process (in /dev/shm when it exists: the targets write a
// file or two per execution) and removed at exit.
inline const std::string& scratch_dir() {
  static const std::string dir = [] {
    std::string tmpl = std::string(::access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp") + "/gyrores-fuzz-XXXXXX";
    if (!::mkdtemp(tmpl.data())) std::abort();
    static std::string keep;
    keep = tmpl;
    std::atexit([] {
      std::string cmd = "rm -rf '" + keep + "'";
      if (std::system(cmd.c_str()) != 0) std::perror("gyrores-fuzz: cleanup");
    });
    return tmpl;
  }();
  return dir;
}

// Writes bytes to a file in the scratch directory (plain write: the input of a parser).
inline std::string scratch_file(const std::string& name, std::string_view bytes) {
  const std::string path = scratch_dir() + "/" + name;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();
  if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size()) std::abort();
  std::fclose(f);
  return path;
}

}  // namespace gyrores::fuzz
