// include/gyrores/io/files.hpp: POSIX files with atomic replacement and durability points.
#include <gyrores/io/files.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

#include <gyrores/core/error.hpp>

namespace gyrores {
namespace {

[[noreturn]] void fail(const std::string& what, const std::string& path, int err) {
  throw usage_error(what + " '" + path + "': " + std::strerror(err));
}

}  // namespace

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("cannot read", path, errno);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool file_exists(const std::string& path) { return ::access(path.c_str(), F_OK) == 0; }

void write_file_atomically(const std::string& path, std::string_view content) {
  write_file_atomically(path, [&](const byte_writer& w) { w(content); });
}

void write_file_atomically(const std::string& path, const std::function<void(const byte_writer&)>& fill) {
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) fail("cannot write", path, errno);
  int err = 0;
  try {
    fill([&](std::string_view bytes) {
      if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size()) {
        err = errno;
        throw usage_error("cannot write '" + path + "': " + std::strerror(err));
      }
    });
  } catch (...) {
    std::fclose(f);
    std::remove(tmp.c_str());
    throw;
  }
  bool ok = std::fflush(f) == 0 && ::fsync(::fileno(f)) == 0;
  err = errno;
  ok = (std::fclose(f) == 0) && ok;
  if (ok && std::rename(tmp.c_str(), path.c_str()) != 0) {
    ok = false;
    err = errno;
  }
  if (!ok) {
    std::remove(tmp.c_str());
    fail("cannot write", path, err);
  }
}

void remove_stale_temporaries(const std::string& path) noexcept {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p(path);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  const std::string prefix = p.filename().string() + ".tmp.";
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string digits = name.substr(prefix.size());
    if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    const pid_t pid = pid_t(std::stol(digits));
    // A live process (ours included) may still be writing it; EPERM means alive too.
    if (pid > 0 && ::kill(pid, 0) != 0 && errno == ESRCH) fs::remove(it->path(), ec);
  }
}

std::uint64_t file_size(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) fail("cannot read", path, errno);
  return std::uint64_t(st.st_size);
}

void read_file_range(const std::string& path, std::uint64_t offset, std::uint64_t length, std::size_t piece,
                     const std::function<void(const void*, std::size_t)>& fn) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) fail("cannot read", path, errno);
  struct closer {
    std::FILE* f;
    ~closer() { std::fclose(f); }
  } close_at_end{f};
  if (::fseeko(f, off_t(offset), SEEK_SET) != 0) fail("cannot read", path, errno);
  if (piece == 0) piece = 1;
  std::unique_ptr<std::max_align_t[]> buf(new std::max_align_t[(piece + sizeof(std::max_align_t) - 1) / sizeof(std::max_align_t)]);
  while (length > 0) {
    const std::size_t n = std::size_t(std::min<std::uint64_t>(length, piece));
    if (std::fread(buf.get(), 1, n, f) != n) {
      if (std::ferror(f)) fail("cannot read", path, errno);
      throw usage_error("cannot read '" + path + "': shorter than expected");
    }
    fn(buf.get(), n);
    length -= n;
  }
}

void ensure_directory(const std::string& dir) {
  if (dir.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw usage_error("cannot create directory '" + dir + "'" + (ec ? ": " + ec.message() : std::string()));
}

void truncate_file(const std::string& path, std::uint64_t size) {
  if (::truncate(path.c_str(), off_t(size)) != 0) fail("cannot truncate", path, errno);
}

void rename_file(const std::string& from, const std::string& to) {
  if (std::rename(from.c_str(), to.c_str()) != 0) fail("cannot rename", from, errno);
}

void remove_file(const std::string& path) noexcept { std::remove(path.c_str()); }

append_file::append_file(const std::string& path, mode m) : path_(path) {
  f_ = std::fopen(path.c_str(), m == mode::create ? "wb" : "ab");
  if (!f_) fail(m == mode::create ? "cannot create" : "cannot open", path, errno);
}

append_file::~append_file() {
  if (f_) std::fclose(f_);
}

append_file::append_file(append_file&& o) noexcept : f_(o.f_), path_(std::move(o.path_)) { o.f_ = nullptr; }

append_file& append_file::operator=(append_file&& o) noexcept {
  if (this != &o) {
    if (f_) std::fclose(f_);
    f_ = o.f_;
    path_ = std::move(o.path_);
    o.f_ = nullptr;
  }
  return *this;
}

void append_file::write(std::string_view bytes) {
  if (!f_) throw usage_error("cannot write '" + path_ + "': not open");
  if (bytes.empty()) return;  // fwrite's pointer must not be null, and an empty view's may be
  if (std::fwrite(bytes.data(), 1, bytes.size(), f_) != bytes.size()) fail("cannot write", path_, errno);
}

void append_file::sync() {
  if (!f_) return;
  // After a failed write (a full disk) the stream may have dropped buffered bytes that an
  // earlier write() reported as written: nothing may be declared durable any more.
  if (std::ferror(f_)) throw usage_error("cannot write '" + path_ + "': an earlier write failed");
  if (std::fflush(f_) != 0) fail("cannot write", path_, errno);
  if (::fsync(::fileno(f_)) != 0) fail("cannot sync", path_, errno);
}

void append_file::close() {
  if (!f_) return;
  sync();
  std::FILE* f = f_;
  f_ = nullptr;
  if (std::fclose(f) != 0) fail("cannot close", path_, errno);
}

}  // namespace gyrores
