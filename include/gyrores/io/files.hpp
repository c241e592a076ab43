// Files, the one place gyrores touches the file system (POSIX). The rules every output follows
// (regular files only, no links followed, unpredictable O_EXCL temporaries, modes kept, locks,
// size caps) are docs/formats.md's "Atomicity", "File safety and locks" and "Size caps".
// Every failure throws usage_error naming the path and the system's reason; a failed write never
// leaves a half-written file under the final name.
#pragma once
#include <cstdint>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace gyrores {

// The whole file, at most max_bytes ("'PATH' is larger than N bytes (the limit for WHAT)"). A
// pipe or device is read until its end or the cap, never trusted for its size.
inline constexpr std::uint64_t default_read_limit = std::uint64_t(256) << 20;
inline constexpr std::uint64_t certificate_read_limit = std::uint64_t(4) << 20;
inline constexpr std::uint64_t sweep_json_read_limit = std::uint64_t(64) << 20;  // states, summaries
std::string read_file(const std::string& path, std::uint64_t max_bytes = default_read_limit,
                      const char* what = "a gyrores input");

bool file_exists(const std::string& path);

// Refuses an input that is missing, a directory, or (unless `allow_stream`) not a regular file:
// merge reads its inputs twice and by offset, which a pipe or device cannot give.
void check_input_path(const std::string& path, bool allow_stream = false);

// Refuses an output that exists and is not a regular file, or whose directory is missing or not
// writable. Commands call it for every output before any work.
void check_output_path(const std::string& path);

// Replaces `path` atomically (check_output_path, then PATH.tmp.PID.RANDOM, fsync, the replaced
// file's mode, rename); on failure `path` is untouched. The second form streams: `fill` gets a
// function that appends bytes, and an exception from it is rethrown after the cleanup.
void write_file_atomically(const std::string& path, std::string_view content);
using byte_writer = std::function<void(std::string_view)>;
void write_file_atomically(const std::string& path, const std::function<void(const byte_writer&)>& fill);

// For files another program writes (gnuplot's images): a new mode-700 directory beside `near`
// (same file system, so install_file's rename is atomic) in which nobody else can plant a file.
std::string make_private_directory(const std::string& near);
void remove_private_directory(const std::string& dir) noexcept;  // the directory and the files in it

// Moves the finished regular file `tmp` over `path` with write_file_atomically's rules; on
// failure `tmp` is removed and `path` is untouched.
void install_file(const std::string& tmp, const std::string& path);

// Removes `path.tmp.PID[.RANDOM]` left by a killed write_file_atomically whose PID no longer runs.
void remove_stale_temporaries(const std::string& path) noexcept;

std::uint64_t file_size(const std::string& path);

// Bytes [offset, offset + length), passed to `fn` in order in pieces of at most `piece` bytes
// (one reused buffer, aligned for any type); usage_error if the file is shorter.
void read_file_range(const std::string& path, std::uint64_t offset, std::uint64_t length, std::size_t piece,
                     const std::function<void(const void* data, std::size_t bytes)>& fn);

void ensure_directory(const std::string& dir);  // and its parents

// A path of a command and what it is for in messages ("--out", "input", ...).
struct named_path {
  std::string role;
  std::string path;
};
// usage_error "ROLE1 'P1' and ROLE2 'P2' are the same file" if two non-empty paths name one file
// (the same device and inode, or the same canonical path when missing).
void check_distinct_paths(const std::vector<named_path>& paths);

// PATH.lock (a command checks it against its other paths too).
std::string path_lock_file(const std::string& path);

// An exclusive flock on PATH.lock, held until destruction, which removes the lock file; locks on
// distinct paths nest. acquire() does not wait: "'PATH' is in use by another gyrores run (pid N)",
// unless `on_busy` is given, which is called once with that message and the lock then waited for
// (see sweep_files::on_lock_wait). A PATH.lock that is not a gyrores lock file is refused, never
// truncated or removed.
class path_lock {
 public:
  path_lock() = default;
  static path_lock acquire(const std::string& path, const std::function<void(const std::string&)>& on_busy = {});
  // For an input: fails as acquire() does if a writer holds PATH.lock; creates no lock file.
  static void check_not_written(const std::string& path);
  ~path_lock();
  path_lock(path_lock&& o) noexcept;
  path_lock& operator=(path_lock&& o) noexcept;
  path_lock(const path_lock&) = delete;
  path_lock& operator=(const path_lock&) = delete;

 private:
  int fd_ = -1;
  std::string lock_path_;
};

void truncate_file(const std::string& path, std::uint64_t size);

// Gives the regular file `path` the mode of `replaced` if that is a regular file, so that a file
// renamed over it keeps its mode (a mode-600 rows file stays 600).
void keep_mode_of(const std::string& replaced, const std::string& path);

void rename_file(const std::string& from, const std::string& to);  // same file system: atomic
void remove_file(const std::string& path) noexcept;                 // if it exists

// An output written in pieces (created or appended to); sync() makes everything written so far
// durable, which is what a checkpoint needs. Once a write() has failed, sync() and close() fail.
class append_file {
 public:
  enum class mode { create, append };
  append_file() = default;
  append_file(const std::string& path, mode m);
  ~append_file();
  append_file(const append_file&) = delete;
  append_file& operator=(const append_file&) = delete;
  append_file(append_file&& o) noexcept;
  append_file& operator=(append_file&& o) noexcept;

  bool is_open() const { return f_ != nullptr; }
  const std::string& path() const { return path_; }
  void write(std::string_view bytes);
  void sync();
  void close();  // syncs first

 private:
  std::FILE* f_ = nullptr;
  std::string path_;
};

}  // namespace gyrores
