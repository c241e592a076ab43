// Files, the one place gyrores touches the file system (POSIX): whole-file reads, atomic
// replacement, and append-only files with explicit durability points (the sweep's rows and
// resume state, docs/formats.md).
//
// Every failure throws usage_error naming the path and the system's reason: the user named a
// path that cannot be read or written (a missing directory, no permission, a full disk). A
// failed write never leaves a half-written file under the final name.
//
// Safety rules every output follows (docs/formats.md, "Files"): an output that exists must be a
// regular file (a directory, device, FIFO or symbolic link is refused up front, never replaced
// or followed); temporaries are created with O_CREAT | O_EXCL | O_NOFOLLOW under an unpredictable
// name, so nothing planted beside the output is ever written through; a replaced file keeps its
// permission bits. Inputs are read with a size cap.
#pragma once
#include <cstdint>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace gyrores {

// The whole file as bytes, at most max_bytes of them: usage_error "'PATH' is larger than N
// bytes (the limit for WHAT)" beyond, and "'PATH' is a directory" for a directory. The file may
// be a pipe or device (read until its end or the cap, never trusted for its size).
// The caps (why these sizes: docs/formats.md, "Size caps"):
inline constexpr std::uint64_t default_read_limit = std::uint64_t(256) << 20;
inline constexpr std::uint64_t certificate_read_limit = std::uint64_t(4) << 20;   // 4 MiB
inline constexpr std::uint64_t sweep_json_read_limit = std::uint64_t(64) << 20;   // 64 MiB: states, summaries
std::string read_file(const std::string& path, std::uint64_t max_bytes = default_read_limit,
                      const char* what = "a gyrores input");

bool file_exists(const std::string& path);

// Refuses (usage_error, one line) an input that is missing, a directory, or (unless
// `allow_stream`) not a regular file: merge reads its inputs twice and by offset, which a pipe or
// device cannot give.
void check_input_path(const std::string& path, bool allow_stream = false);

// Refuses (usage_error, one line) an output path that cannot be a gyrores output: it exists and
// is not a regular file (directory, device, FIFO, socket, symbolic link), or its directory is
// missing or not writable. Commands call it for every output before any work.
void check_output_path(const std::string& path);

// Replaces `path` atomically: check_output_path, then the content goes to a new temporary file
// in the same directory (path + ".tmp." + pid + "." + 16 random hex digits, created with
// O_CREAT | O_EXCL | O_NOFOLLOW), is fsync'ed, given the replaced file's permission bits, and
// renamed over `path` (the directory is then fsync'ed). On failure the temporary file is
// removed and `path` is untouched.
void write_file_atomically(const std::string& path, std::string_view content);

// For files another program writes (gnuplot's images): a new directory, mode 700, in the
// directory of `near` (so that a rename from it is atomic), named ".gyrores-tmp.XXXXXX" by
// mkdtemp. Nobody else can create, replace or link anything in it, so the program may open
// names in it freely. The caller removes it (remove_private_directory).
std::string make_private_directory(const std::string& near);
void remove_private_directory(const std::string& dir) noexcept;  // the directory and the files in it

// Moves a finished file `tmp` (in a private directory on `path`'s file system) over `path` with
// write_file_atomically's rules: check_output_path(path), the replaced file's permission bits,
// fsync, rename, the directory fsync'ed. `tmp` must be a regular file (not followed if a link).
// On failure `tmp` is removed and `path` is untouched.
void install_file(const std::string& tmp, const std::string& path);

// Removes the temporary files of write_file_atomically(path, ...) that a killed process left
// behind: `path.tmp.PID[.RANDOM]` for a PID no longer running (never throws). Run before a
// sweep starts.
void remove_stale_temporaries(const std::string& path) noexcept;

// The same for content too large to hold: `fill` is given a function that appends bytes to the
// temporary file. An exception from `fill` removes the temporary file and is rethrown.
using byte_writer = std::function<void(std::string_view)>;
void write_file_atomically(const std::string& path, const std::function<void(const byte_writer&)>& fill);

// The size of a file in bytes.
std::uint64_t file_size(const std::string& path);

// Bytes [offset, offset + length) of a file, read in order in pieces of at most `piece` bytes;
// each piece is passed to `fn` in one buffer (reused, aligned for any type). usage_error if the
// file cannot be read or is shorter.
void read_file_range(const std::string& path, std::uint64_t offset, std::uint64_t length, std::size_t piece,
                     const std::function<void(const void* data, std::size_t bytes)>& fn);

// Creates a directory and its parents (nothing to do if it exists).
void ensure_directory(const std::string& dir);

// What names a file for collision checks: "dev:inode" when it exists, else its canonical path
// (symbolic links of the existing directories resolved), so that two spellings of one file,
// existing or not, give the same key.
std::string file_identity(const std::string& path);

// A named path of a command: what it is for (in messages) and the path.
struct named_path {
  std::string role;  // "--out", "--summary", "input", ...
  std::string path;
};
// usage_error "ROLE1 'P1' and ROLE2 'P2' are the same file" if two of the non-empty paths name
// one file (file_identity). Commands call it on all their inputs, outputs and scratch files
// before any work.
void check_distinct_paths(const std::vector<named_path>& paths);

// The lock file of PATH: PATH.lock (a command checks it against its other paths too).
std::string path_lock_file(const std::string& path);

// An exclusive advisory lock (flock) on PATH.lock, held until destruction, when the lock file
// is removed. acquire() does not wait: if another process holds it, usage_error
// "'PATH' is in use by another gyrores run (pid N)" -- unless `on_busy` is given, which is then
// called once with that message and the lock waited for (a path the user did not name, shared
// by default: see sweep_files::on_lock_wait). Locks taken by one process on distinct
// paths nest. The lock file holds the owner's pid, for that message only. An existing PATH.lock
// that is not such a file (not regular, or other content) is refused, never truncated or removed.
class path_lock {
 public:
  path_lock() = default;
  static path_lock acquire(const std::string& path, const std::function<void(const std::string&)>& on_busy = {});
  // For an input: fails as acquire() does if a writer holds PATH.lock, else takes nothing (no
  // lock file is created beside inputs).
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

// Cuts a file to `size` bytes (used to drop what a resume does not trust).
void truncate_file(const std::string& path, std::uint64_t size);

// Gives `path` (a regular file) the permission bits of `replaced` when that exists as a regular
// file, so that a file renamed over it keeps its mode as write_file_atomically's do (a mode-600
// rows file stays 600). Nothing to do when `replaced` does not exist.
void keep_mode_of(const std::string& replaced, const std::string& path);

// Renames `from` over `to` (same file system: atomic).
void rename_file(const std::string& from, const std::string& to);

// Removes a file if it exists (never throws).
void remove_file(const std::string& path) noexcept;

// An output file written in pieces: created (or truncated) or opened for appending; sync()
// makes everything written so far durable (fflush + fsync), which is what a checkpoint needs.
// Once a write() has failed, sync() and close() fail too.
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
