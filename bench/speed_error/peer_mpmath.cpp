// speed_error/peer_mpmath.hpp: the task file, the child process, its rows.
#include "peer_mpmath.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <unistd.h>
#include "testing/test_support.hpp"

namespace gyrores::bench {

namespace {

// "a\tb\t" -> {"a", "b", ""}.
std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t tab; (tab = line.find('\t', start)) != std::string::npos; start = tab + 1)
    out.push_back(line.substr(start, tab - start));
  out.push_back(line.substr(start));
  return out;
}

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char ch : s) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

struct mpmath_task {
  std::string pair, precision;
};

// Why the peer cannot run (missing script, no mpmath), or "".
std::string unavailable_reason(const std::string& python, const std::string& script) {
  const std::string probe = shell_quote(python) + " -c 'import mpmath' >/dev/null 2>&1";
  if (std::ifstream(script).fail()) return "skipped: the peer script " + script + " is missing";
  if (std::system(probe.c_str()) != 0) return "skipped: " + python + " cannot import mpmath (Debian: python3-mpmath)";
  return "";
}

// Writes the task file (one line per pair and precision among 50, 100 and 1000 digits; see
// mpmath_peer.py) and returns the tasks by id.
std::vector<mpmath_task> write_tasks(const std::string& task_file, const std::vector<bench_pair>& pairs,
                                     const std::vector<precision>& precisions,
                                     const std::map<std::string, reference>& refs) {
  std::vector<mpmath_task> tasks;
  std::ofstream tf(task_file);
  for (const auto& bp : pairs) {
    const reference& ref = refs.at(bp.name);
    for (const auto& pr : precisions) {
      if (!pr.is_mp() || (pr.digits != 50 && pr.digits != 100 && pr.digits != 1000)) continue;
      // Start: theta_first to ceil(log10 a) + 8 digits; second point 1e-4 half-periods further.
      const unsigned lg = unsigned(boost::multiprecision::msb(bp.order()) * 0.30103) + 2;
      scoped_digits d(2 * lg + 40);
      mpfr_real th(ref.theta_first);
      const std::string x0 = th.str(std::streamsize(lg + 8), std::ios_base::scientific);
      mpfr_real x1 = mpfr_real(x0) + boost::math::constants::pi<mpfr_real>() / mpfr_real(bp.p.tau()) / 10000;
      tf << tasks.size() << '\t' << bp.p.tau().str() << '\t' << bp.p.sigma().str() << '\t' << pr.digits << '\t' << x0
         << '\t' << x1.str(std::streamsize(2 * lg + 20), std::ios_base::scientific) << '\n';
      tasks.push_back({bp.name, pr.name});
    }
  }
  return tasks;
}

// One result line of the peer (id, median s, repetitions, calls, evaluations, theta, r, error)
// as a row, scored; nullopt for a line that is not one.
std::optional<measurement> row_of_line(const std::string& line, const std::vector<mpmath_task>& tasks,
                                       const std::map<std::string, reference>& refs) {
  auto f = split_tabs(line);
  if (f.size() < 8) return std::nullopt;
  const std::size_t id = std::stoul(f[0]);
  if (id >= tasks.size()) return std::nullopt;
  measurement m;
  m.method = "mpmath_findroot";
  m.pair = tasks[id].pair;
  m.precision = tasks[id].precision;
  const double med = std::strtod(f[1].c_str(), nullptr);
  m.repetitions = std::atoi(f[2].c_str());
  m.iterations = std::atoll(f[3].c_str());
  if (!f[7].empty() || !(med == med)) {
    m.failed = true;
    m.note = "mpmath failed: " + f[7];
    m.digits_theta = m.digits_r = 0;
  } else {
    m.median_ns = med * 1e9;
    outcome o;
    o.theta = f[5];
    o.r_res = f[6];
    o.evaluations = std::stoull(f[4]);
    score(m, o, refs.at(m.pair));
    m.note = "timed in Python (process_time)";
  }
  return m;
}

// Reads the peer's output: "# ..." sets the status, every other line may be a row.
void read_peer_output(FILE* pipe, const std::vector<mpmath_task>& tasks, const std::map<std::string, reference>& refs,
                      mpmath_run& run) {
  std::vector<char> buf(1 << 16);
  std::string acc;
  while (fgets(buf.data(), int(buf.size()), pipe)) {
    acc += buf.data();
    if (acc.empty() || acc.back() != '\n') continue;
    const std::string line = acc.substr(0, acc.size() - 1);
    acc.clear();
    if (line.rfind("# ", 0) == 0) {
      run.status = line.substr(2);
      continue;
    }
    auto m = row_of_line(line, tasks, refs);
    if (!m) continue;
    run.rows.push_back(*m);
    std::fprintf(stderr, "  mpmath_findroot %-8s %-18s %s\n", m->precision.c_str(), m->pair.c_str(),
                 m->failed ? m->note.c_str() : "ok");
  }
}

}  // namespace

mpmath_run run_mpmath_peer(const std::string& python, const std::string& script, const std::vector<bench_pair>& pairs,
                           const std::vector<precision>& precisions, const std::map<std::string, reference>& refs) {
  mpmath_run run;
  run.status = unavailable_reason(python, script);
  if (!run.status.empty()) return run;
  char tmpl[] = "/tmp/gyrores-bench-mpmath-XXXXXX";
  int fd = mkstemp(tmpl);
  if (fd < 0) {
    run.status = "skipped: no temporary file for the task list";
    return run;
  }
  close(fd);
  const std::string task_file = tmpl;
  const std::vector<mpmath_task> tasks = write_tasks(task_file, pairs, precisions, refs);
  const std::string cmd = shell_quote(python) + " " + shell_quote(script) + " " + shell_quote(task_file);
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) {
    run.status = "skipped: could not start " + python;
    std::remove(task_file.c_str());
    return run;
  }
  read_peer_output(pipe, tasks, refs, run);
  const int rc = pclose(pipe);
  std::remove(task_file.c_str());
  run.available = rc == 0;
  if (rc != 0) run.status += " (the peer exited with status " + std::to_string(rc) + ")";
  return run;
}

}  // namespace gyrores::bench
