// Fuzz target: resuming a sweep from its resume state (io/sweep_files.hpp, docs/formats.md).
// The input is the state file, then (after fuzz_support.hpp's file_separator) the values file;
// both go to the scratch directory and `gyrores sweep --max-order 12 --summary S --resume`
// runs on them in-process (double, one thread). A state that does not fit must give
// usage_error; one that fits continues the 22-pair sweep to the end.
#include <gyrores/core/error.hpp>
#include <gyrores/app/sweep.hpp>
#include <gyrores/io/sweep_files.hpp>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 65536) return -1;
  namespace fz = gyrores::fuzz;
  const auto parts = fz::split(fz::as_text(data, size), fz::file_separator, 2);
  const std::string summary = fz::scratch_dir() + "/s.json";
  fz::scratch_file("s.json.resume", parts[0]);
  fz::scratch_file("s.json.resume.values", parts.size() > 1 ? parts[1] : "");
  gyrores::sweep_config cfg;
  cfg.max_order = 12;
  gyrores::sweep_files files;
  files.summary_path = summary;
  files.resume = true;
  files.checkpoint_seconds = 0;
  gyrores::sweep_engine_options eo;
  eo.threads = 1;
  try {
    const auto rep = gyrores::app::sweep_to_files<double>(cfg, files, eo);
    if (!rep.complete) std::abort();
  } catch (const gyrores::usage_error&) {
  } catch (const gyrores::compute_error&) {
  }
  return 0;
}
