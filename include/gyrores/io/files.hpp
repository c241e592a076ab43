// Files, the one place gyrores touches the file system (POSIX): whole-file reads, atomic
// replacement, and append-only files with explicit durability points (the sweep's rows and
// resume state, docs/formats.md).
//
// Every failure throws usage_error naming the path and the system's reason: the user named a
// path that cannot be read or written (a missing directory, no permission, a full disk). A
// failed write never leaves a half-written file under the final name.
#pragma once
#include <cstdint>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>
#include <string_view>

namespace gyrores {

// The whole file as bytes.
std::string read_file(const std::string& path);

bool file_exists(const std::string& path);

// Replaces `path` atomically: the content goes to a temporary file in the same directory
// (path + ".tmp." + pid), is flushed and fsync'ed, then renamed over `path`. On failure the
// temporary file is removed and `path` is untouched.
void write_file_atomically(const std::string& path, std::string_view content);

// Removes the temporary files of write_file_atomically(path, ...) that a killed process left
// behind: `path.tmp.PID` for a PID no longer running (never throws). Run before a sweep starts.
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

// Cuts a file to `size` bytes (used to drop what a resume does not trust).
void truncate_file(const std::string& path, std::uint64_t size);

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
