// Running the built gyrores executable from a test, and temporary directories.
//
// GYRORES_CLI_PATH is set by tests/CMakeLists.txt for the tests that drive the CLI; it is empty
// when the CLI is not built, and those checks are skipped (cli_available()).
#pragma once
#include <cstdint>
#include <string>

#ifndef GYRORES_CLI_PATH
#define GYRORES_CLI_PATH ""
#endif

namespace gyrores::test {

struct cli_result {
  int status = -1;  // exit status; -1 if the process did not exit normally
  std::string out, err;
};

inline std::string cli_path() { return GYRORES_CLI_PATH; }
inline bool cli_available() { return !cli_path().empty(); }

// Runs `[env] <cli> args` through the shell, capturing stdout and stderr.
cli_result cli_run(const std::string& args, const std::string& env = "");

// Starts `<cli> args` in the background (stdout and stderr to the given files, stdin closed)
// and returns its process id, for tests that signal a running command. max_file_bytes > 0
// limits the size of every file the command writes (RLIMIT_FSIZE, with SIGXFSZ ignored so that
// a write beyond it fails with EFBIG as on a full disk; the two output files count too).
int cli_spawn(const std::string& args, const std::string& out_file, const std::string& err_file,
              std::uint64_t max_file_bytes = 0);
// Waits for a spawned process; returns its exit status, or 128 + signal if a signal ended it.
int cli_wait(int pid);

int count_lines(const std::string& s);

// The whole file, or "" if it cannot be read.
std::string read_text(const std::string& path);
bool path_exists(const std::string& path);

// A fresh empty directory under /tmp, removed with its content when the object goes away.
class temp_dir {
 public:
  explicit temp_dir(const std::string& tag);
  ~temp_dir();
  temp_dir(const temp_dir&) = delete;
  temp_dir& operator=(const temp_dir&) = delete;
  const std::string& path() const { return path_; }
  std::string operator/(const std::string& name) const { return path_ + "/" + name; }
  operator const std::string&() const { return path_; }

 private:
  std::string path_;
};

}  // namespace gyrores::test
