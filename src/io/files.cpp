// include/gyrores/io/files.hpp: POSIX files with atomic replacement and durability points.
#include <gyrores/io/files.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <utility>
#include <vector>

#include <gyrores/core/error.hpp>

namespace gyrores {
namespace {

[[noreturn]] void fail(const std::string& what, const std::string& path, int err) {
  throw usage_error(what + " '" + path + "': " + std::strerror(err));
}

// A descriptor closed when the scope ends, on every path out (errno is read before).
struct fd_guard {
  int fd;
  ~fd_guard() {
    if (fd >= 0) ::close(fd);
  }
  int release() { return std::exchange(fd, -1); }
};

// 16 hex digits from the kernel's random source: a temporary's name nobody can predict.
std::string random_hex() {
  unsigned char b[8] = {};
  std::size_t got = 0;
  if (const fd_guard g{::open("/dev/urandom", O_RDONLY | O_CLOEXEC)}; g.fd >= 0) {
    while (got < sizeof b) {
      const ssize_t n = ::read(g.fd, b + got, sizeof b - got);
      if (n <= 0) break;
      got += std::size_t(n);
    }
  }
  if (got < sizeof b) throw usage_error("cannot read /dev/urandom for a temporary file's name");
  static const char hex[] = "0123456789abcdef";
  std::string s;
  for (unsigned char c : b) {
    s.push_back(hex[c >> 4]);
    s.push_back(hex[c & 15]);
  }
  return s;
}

std::string directory_of(const std::string& path) {
  const auto slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// write(2) until done; false with errno set on failure.
bool write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t k = ::write(fd, p, n);
    if (k < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    p += k;
    n -= std::size_t(k);
  }
  return true;
}

const char* kind_of(mode_t m) {
  if (S_ISDIR(m)) return "a directory";
  if (S_ISLNK(m)) return "a symbolic link";
  if (S_ISCHR(m) || S_ISBLK(m)) return "a device";
  if (S_ISFIFO(m)) return "a FIFO";
  if (S_ISSOCK(m)) return "a socket";
  return "not a regular file";
}

// The end of every atomic replacement: `fd` (open on `tmp`, closed here) gets the replaced file's
// permission bits (a mode-600 output stays 600; a new file keeps 0666 less the umask), is
// fsync'ed and renamed over `path`. On failure `tmp` is removed and `path` is untouched.
void replace_with(int fd, const std::string& tmp, const std::string& path) {
  struct stat old {};
  int err = 0;
  if (::stat(path.c_str(), &old) == 0 && ::fchmod(fd, old.st_mode & 07777) != 0) err = errno;
  else if (::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err == 0 && ::rename(tmp.c_str(), path.c_str()) != 0) err = errno;
  if (err != 0) {
    ::unlink(tmp.c_str());
    fail("cannot write", path, err);
  }
  // The rename itself durable (best effort: some file systems refuse fsync on a directory).
  if (const fd_guard d{::open(directory_of(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)}; d.fd >= 0)
    ::fsync(d.fd);
}

// "dev:inode" when the file exists, else its canonical path (symbolic links of the existing
// directories resolved): two spellings of one file, existing or not, give the same key.
std::string file_identity(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) return "inode:" + std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino);
  std::error_code ec;
  const auto canon = std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
  return "path:" + (ec ? path : canon.string());
}

std::string lock_owner(int fd) {
  char buf[32] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  std::string s(buf, n > 0 ? std::size_t(n) : 0);
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s.empty() || s.find_first_not_of("0123456789") != std::string::npos ? std::string() : " (pid " + s + ")";
}

std::string in_use_message(const std::string& path, int fd) {
  return "'" + path + "' is in use by another gyrores run" + lock_owner(fd);
}

[[noreturn]] void in_use(const std::string& path, int fd) {
  throw usage_error(in_use_message(path, fd) + "; wait for it to end or choose other files");
}

// A file already at PATH.lock is taken over only if it is what a gyrores run leaves there: a
// regular file, empty or holding a pid line. Anything else is the user's (a rows file named
// X.lock, say), which acquire() would otherwise truncate and remove at the end.
bool looks_like_lock_file(int fd) {
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_size > 24) return false;
  char buf[32] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf, 0);
  if (n < 0) return false;
  const std::string s(buf, std::size_t(n));
  if (s.empty()) return true;
  return s.back() == '\n' && s.size() >= 2 && s.find_first_not_of("0123456789") == s.size() - 1;
}

}  // namespace

std::string read_file(const std::string& path, std::uint64_t max_bytes, const char* what) {
  const fd_guard g{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (g.fd < 0) fail("cannot read", path, errno);
  struct stat st {};
  if (::fstat(g.fd, &st) != 0) fail("cannot read", path, errno);
  if (S_ISDIR(st.st_mode)) throw usage_error("cannot read '" + path + "': it is a directory");
  auto too_large = [&] {
    return usage_error("'" + path + "' is larger than " + std::to_string(max_bytes) + " bytes (the limit for " + what + ")");
  };
  if (S_ISREG(st.st_mode) && std::uint64_t(st.st_size) > max_bytes) throw too_large();
  std::string s;
  char buf[1 << 16];
  for (;;) {
    const ssize_t n = ::read(g.fd, buf, sizeof buf);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("cannot read", path, errno);
    }
    if (n == 0) return s;
    // A device or pipe (or a file growing while read) is held to the same cap.
    if (s.size() + std::size_t(n) > max_bytes) throw too_large();
    s.append(buf, std::size_t(n));
  }
}

bool file_exists(const std::string& path) { return ::access(path.c_str(), F_OK) == 0; }

void check_input_path(const std::string& path, bool allow_stream) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) fail("cannot read", path, errno);
  if (S_ISDIR(st.st_mode)) throw usage_error("cannot read '" + path + "': it is a directory");
  if (!allow_stream && !S_ISREG(st.st_mode))
    throw usage_error("cannot read '" + path + "': it is " + kind_of(st.st_mode) + ", not a regular file");
}

void check_output_path(const std::string& path) {
  if (path.empty()) throw usage_error("an output path is empty");
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0) {
    if (!S_ISREG(st.st_mode))
      throw usage_error("refusing to write '" + path + "': it is " + kind_of(st.st_mode) + ", not a regular file");
  } else if (errno != ENOENT) {
    fail("cannot write", path, errno);
  }
  const std::string dir = directory_of(path);
  struct stat ds {};
  if (::stat(dir.c_str(), &ds) != 0) fail("cannot write", path, errno);
  if (!S_ISDIR(ds.st_mode)) throw usage_error("cannot write '" + path + "': '" + dir + "' is not a directory");
  if (::access(dir.c_str(), W_OK | X_OK) != 0) fail("cannot write", path, errno);
}

void write_file_atomically(const std::string& path, std::string_view content) {
  write_file_atomically(path, [&](const byte_writer& w) { w(content); });
}

void write_file_atomically(const std::string& path, const std::function<void(const byte_writer&)>& fill) {
  check_output_path(path);
  const std::string tmp = path + ".tmp." + std::to_string(::getpid()) + "." + random_hex();
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) fail("cannot write", path, errno);
  try {
    fill([&](std::string_view bytes) {
      if (!write_all(fd, bytes.data(), bytes.size())) fail("cannot write", path, errno);
    });
  } catch (...) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw;
  }
  replace_with(fd, tmp, path);
}

std::string make_private_directory(const std::string& near) {
  std::string templ = directory_of(near) + "/.gyrores-tmp.XXXXXX";
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  if (::mkdtemp(buf.data()) == nullptr) fail("cannot create a temporary directory beside", near, errno);
  return std::string(buf.data());
}

void remove_private_directory(const std::string& dir) noexcept {
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
}

void install_file(const std::string& tmp, const std::string& path) {
  fd_guard g{-1};
  try {
    check_output_path(path);
    g.fd = ::open(tmp.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (g.fd < 0) fail("cannot write", path, errno);
    struct stat st {};
    if (::fstat(g.fd, &st) != 0 || !S_ISREG(st.st_mode)) fail("cannot write", path, EINVAL);
  } catch (...) {
    ::unlink(tmp.c_str());
    throw;
  }
  replace_with(g.release(), tmp, path);
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
    std::string rest = name.substr(prefix.size());
    // PID, or PID.RANDOM (io/files.hpp)
    const auto dot = rest.find('.');
    const std::string digits = rest.substr(0, dot);
    if (dot != std::string::npos && (rest.size() - dot - 1 != 16 ||
                                     rest.find_first_not_of("0123456789abcdef", dot + 1) != std::string::npos))
      continue;
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    const pid_t pid = pid_t(std::stol(digits));
    // A live process (ours included) may still be writing it; EPERM means alive too.
    if (pid > 0 && ::kill(pid, 0) != 0 && errno == ESRCH) fs::remove(it->path(), ec);
  }
}

void check_distinct_paths(const std::vector<named_path>& paths) {
  std::vector<std::string> ids(paths.size());
  for (std::size_t i = 0; i < paths.size(); ++i)
    if (!paths[i].path.empty()) ids[i] = file_identity(paths[i].path);
  for (std::size_t i = 0; i < paths.size(); ++i)
    for (std::size_t j = i + 1; j < paths.size(); ++j)
      if (!ids[i].empty() && ids[i] == ids[j])
        throw usage_error(paths[i].role + " '" + paths[i].path + "' and " + paths[j].role + " '" + paths[j].path +
                          "' are the same file");
}

std::string path_lock_file(const std::string& path) { return path + ".lock"; }

path_lock path_lock::acquire(const std::string& path, const std::function<void(const std::string&)>& on_busy) {
  const std::string lp = path_lock_file(path);
  bool told = false;
  for (int attempt = 0; attempt < 100; ++attempt) {
    fd_guard g{::open(lp.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0666)};
    if (g.fd < 0) fail("cannot create the lock file", lp, errno);
    if (!looks_like_lock_file(g.fd))
      throw usage_error("'" + lp + "' (the lock file of '" + path +
                        "') exists and is not a gyrores lock file: move it away or choose other files");
    if (::flock(g.fd, LOCK_EX | LOCK_NB) != 0) {
      int err = errno;
      if (err == EWOULDBLOCK) {
        if (!on_busy) in_use(path, g.fd);
        if (!told) on_busy(in_use_message(path, g.fd));
        told = true;
        while ((err = ::flock(g.fd, LOCK_EX) == 0 ? 0 : errno) == EINTR) {
        }
      }
      if (err != 0) fail("cannot lock", lp, err);
    }
    // The holder before us may have removed the file after we opened it (it unlinks, then
    // unlocks): our lock is then on a name nobody else sees. Retry on the current file.
    struct stat a {}, b {};
    if (::fstat(g.fd, &a) != 0 || ::stat(lp.c_str(), &b) != 0 || a.st_dev != b.st_dev || a.st_ino != b.st_ino)
      continue;
    const std::string pid = std::to_string(::getpid()) + "\n";
    if (::ftruncate(g.fd, 0) != 0 || ::pwrite(g.fd, pid.data(), pid.size(), 0) != ssize_t(pid.size())) {
      const int err = errno;
      ::unlink(lp.c_str());
      fail("cannot write the lock file", lp, err);
    }
    path_lock l;
    l.fd_ = g.release();
    l.lock_path_ = lp;
    return l;
  }
  throw usage_error("cannot lock '" + path + "': its lock file keeps changing");
}

void path_lock::check_not_written(const std::string& path) {
  const fd_guard g{::open(path_lock_file(path).c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC)};
  if (g.fd < 0) return;  // no lock file: nobody writes it now
  if (::flock(g.fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK) in_use(path, g.fd);
}  // closing releases the shared lock

path_lock::~path_lock() {
  if (fd_ < 0) return;
  ::unlink(lock_path_.c_str());  // while still holding it (see acquire)
  ::close(fd_);
}

path_lock::path_lock(path_lock&& o) noexcept : fd_(std::exchange(o.fd_, -1)), lock_path_(std::move(o.lock_path_)) {}

// The lock held before goes with `o`.
path_lock& path_lock::operator=(path_lock&& o) noexcept {
  std::swap(fd_, o.fd_);
  std::swap(lock_path_, o.lock_path_);
  return *this;
}

std::uint64_t file_size(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) fail("cannot read", path, errno);
  return std::uint64_t(st.st_size);
}

void read_file_range(const std::string& path, std::uint64_t offset, std::uint64_t length, std::size_t piece,
                     const std::function<void(const void*, std::size_t)>& fn) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) fail("cannot read", path, errno);
  if (::fseeko(f.get(), off_t(offset), SEEK_SET) != 0) fail("cannot read", path, errno);
  if (piece == 0) piece = 1;
  std::unique_ptr<std::max_align_t[]> buf(new std::max_align_t[(piece + sizeof(std::max_align_t) - 1) / sizeof(std::max_align_t)]);
  while (length > 0) {
    const std::size_t n = std::size_t(std::min<std::uint64_t>(length, piece));
    if (std::fread(buf.get(), 1, n, f.get()) != n) {
      if (std::ferror(f.get())) fail("cannot read", path, errno);
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
  const fd_guard g{::open(path.c_str(), O_WRONLY | O_NOFOLLOW | O_CLOEXEC)};
  if (g.fd < 0) fail("cannot truncate", path, errno);
  struct stat st {};
  if (::fstat(g.fd, &st) != 0) fail("cannot truncate", path, errno);
  if (!S_ISREG(st.st_mode)) fail("cannot truncate", path, EINVAL);
  if (::ftruncate(g.fd, off_t(size)) != 0) fail("cannot truncate", path, errno);
}

void keep_mode_of(const std::string& replaced, const std::string& path) {
  struct stat old {};
  if (::lstat(replaced.c_str(), &old) != 0 || !S_ISREG(old.st_mode)) return;
  const fd_guard g{::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC)};
  if (g.fd < 0) fail("cannot change the mode of", path, errno);
  struct stat st {};
  if (::fstat(g.fd, &st) != 0) fail("cannot change the mode of", path, errno);
  if (!S_ISREG(st.st_mode)) fail("cannot change the mode of", path, EINVAL);
  if (::fchmod(g.fd, old.st_mode & 07777) != 0) fail("cannot change the mode of", path, errno);
}

void rename_file(const std::string& from, const std::string& to) {
  if (std::rename(from.c_str(), to.c_str()) != 0) fail("cannot rename", from, errno);
}

void remove_file(const std::string& path) noexcept { std::remove(path.c_str()); }

append_file::append_file(const std::string& path, mode m) : path_(path) {
  // Never through a symbolic link, never onto a device or directory (io/files.hpp).
  const int flags = O_WRONLY | O_NOFOLLOW | O_CLOEXEC | (m == mode::create ? O_CREAT | O_TRUNC : O_CREAT | O_APPEND);
  const char* what = m == mode::create ? "cannot create" : "cannot open";
  // O_NONBLOCK: a FIFO planted there must not block the open; cleared for the regular file.
  fd_guard g{::open(path.c_str(), flags | O_NONBLOCK, 0666)};
  if (g.fd < 0) fail(what, path, errno);
  struct stat st {};
  if (::fstat(g.fd, &st) != 0 || !S_ISREG(st.st_mode) || ::fcntl(g.fd, F_SETFL, flags & O_APPEND) != 0)
    throw usage_error(std::string(what) + " '" + path + "': not a regular file");
  f_ = ::fdopen(g.fd, m == mode::create ? "wb" : "ab");
  if (!f_) fail(what, path, errno);
  g.release();
}

append_file::~append_file() {
  if (f_) std::fclose(f_);
}

append_file::append_file(append_file&& o) noexcept : f_(std::exchange(o.f_, nullptr)), path_(std::move(o.path_)) {}

// The file open before goes with `o`.
append_file& append_file::operator=(append_file&& o) noexcept {
  std::swap(f_, o.f_);
  std::swap(path_, o.path_);
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
