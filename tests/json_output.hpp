// The JSON a foldlab run printed on stdout, for tests of commands with --json or --report.
#pragma once

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "process.hpp"

namespace foldlab::testing {

// Expects the run to have succeeded and its stdout to be JSON; a null value (and a test failure
// naming what was printed) otherwise.
inline nlohmann::json json_output(const RunResult& r) {
  EXPECT_EQ(r.exit_status, 0) << r.err;
  try {
    return nlohmann::json::parse(r.out);
  } catch (const nlohmann::json::exception& e) {
    ADD_FAILURE() << "stdout is not JSON: " << e.what() << "\n" << r.out;
    return nlohmann::json();
  }
}

}  // namespace foldlab::testing
