// Catch2 checks shared by the tests that drive the gyrores executable (the runner itself is
// src/testing/cli_run.hpp, which bench/ and proofs/ use without Catch2).
#pragma once
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>
#include <string>

#include "testing/cli_run.hpp"

namespace gyrores::test {

// The CLI refuses `args` cleanly: exit status `status` (2: usage error, 3: nothing to compute),
// nothing on stdout, one line on stderr, containing `needle` when one is given.
inline void check_rejected(const std::string& args, int status = 2, const std::string& needle = "") {
  INFO(args);
  const auto r = cli_run(args);
  CHECK(r.status == status);
  CHECK(r.out.empty());
  CHECK(count_lines(r.err) == 1);
  if (!needle.empty()) CHECK(r.err.find(needle) != std::string::npos);
}

// Runs `args`, which must succeed with nothing on stderr; returns stdout parsed as JSON.
inline nlohmann::json cli_json(const std::string& args) {
  INFO(args);
  const auto r = cli_run(args);
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  return nlohmann::json::parse(r.out);
}

}  // namespace gyrores::test
