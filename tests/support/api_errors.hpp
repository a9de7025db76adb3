// Test support for the public API's tests (tests/api/): the message of the
// InputError a call throws, and the message the CLI printed for the same
// mistake, so a test can require the two to be equal.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>

#include "hydrocoef/error.hpp"
#include "tests/support/run_cli.hpp"

namespace hydrocoef::test {

/// The message of the InputError `call` throws (a test failure when it throws none).
inline std::string error_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const hydrocoef::InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "expected hydrocoef::InputError";
  return {};
}

/// The message after "hydrocoef: error: " on the CLI's one line of stderr;
/// the exit code must be 2.
inline std::string cli_error(const CliResult& result) {
  const std::string prefix = "hydrocoef: error: ";
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_EQ(result.err.rfind(prefix, 0), 0u) << result.err;
  std::string message = result.err.substr(std::min(prefix.size(), result.err.size()));
  while (!message.empty() && message.back() == '\n') message.pop_back();
  return message;
}

}  // namespace hydrocoef::test
