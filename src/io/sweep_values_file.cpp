// include/gyrores/io/sweep_values_file.hpp: values files, written and replayed in pieces.
#include <gyrores/io/sweep_values_file.hpp>

#include <cstdio>
#include <cstring>
#include <string_view>

#include <gyrores/core/error.hpp>
#include <gyrores/io/files.hpp>

namespace gyrores {
namespace {

const char values_magic[] = "GYRVAL01";
constexpr std::uint64_t header_bytes = 16;
constexpr std::size_t piece_bytes = std::size_t(1) << 20;

// FNV-1a, 64 bits, over bytes fed in pieces, with the count and range of the doubles.
struct digest_builder {
  std::uint64_t hash = 14695981039346656037ull, count = 0;
  double lo = 0, hi = 0;
  bool any = false;
  void add(const double* d, std::size_t k) {
    const auto* p = reinterpret_cast<const unsigned char*>(d);
    for (std::size_t i = 0; i < k * sizeof(double); ++i) hash = (hash ^ p[i]) * 1099511628211ull;
    for (std::size_t i = 0; i < k; ++i) {
      if (d[i] != d[i]) continue;  // NaN: in the hash, not the range
      if (!any || d[i] < lo) lo = d[i];
      if (!any || d[i] > hi) hi = d[i];
      any = true;
    }
    count += k;
  }
  json result() const {
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    json j;
    j["count"] = count;
    j["min"] = any ? json(lo) : json(nullptr);
    j["max"] = any ? json(hi) : json(nullptr);
    j["fnv1a64"] = hex;
    return j;
  }
};

}  // namespace

json sweep_values_digest(const sweep_values& v) {
  digest_builder b;
  v.replay([&](const double* d, std::size_t k) { b.add(d, k); });
  return b.result();
}

sweep_value_source sweep_values_file_source(const std::string& path, std::uint64_t offset, std::uint64_t count) {
  return [path, offset, count](const sweep_value_sink& sink) {
    read_file_range(path, offset, count * sizeof(double), piece_bytes, [&](const void* data, std::size_t bytes) {
      sink(static_cast<const double*>(data), bytes / sizeof(double));
    });
  };
}

json sweep_write_values_file(const std::string& path, const sweep_values& v) {
  digest_builder b;
  write_file_atomically(path, [&](const byte_writer& w) {
    const std::uint64_t n = v.size();
    w(std::string_view(values_magic, 8));
    w(std::string_view(reinterpret_cast<const char*>(&n), sizeof n));
    v.replay([&](const double* d, std::size_t k) {
      b.add(d, k);
      w(std::string_view(reinterpret_cast<const char*>(d), k * sizeof(double)));
    });
  });
  return b.result();
}

sweep_values sweep_read_values_file(const std::string& path) {
  const std::uint64_t size = file_size(path);
  std::string head;
  if (size >= header_bytes)
    read_file_range(path, 0, header_bytes, header_bytes,
                    [&](const void* d, std::size_t k) { head.assign(static_cast<const char*>(d), k); });
  if (head.size() < header_bytes || head.compare(0, 8, values_magic) != 0)
    throw usage_error("'" + path + "' is not a gyrores values file");
  std::uint64_t n = 0;
  std::memcpy(&n, head.data() + 8, sizeof n);
  // Compared by division: 16 + 8 n wraps around for n >= 2^61.
  if ((size - header_bytes) % sizeof(double) != 0 || n != (size - header_bytes) / sizeof(double))
    throw usage_error("'" + path + "' is truncated");
  sweep_values v;
  v.add_source(sweep_values_file_source(path, header_bytes, n), n);
  return v;
}

}  // namespace gyrores
