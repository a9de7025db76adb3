// Test support: run an action that must throw InputError, and check that the
// message mentions each expected piece (file, line, the value found, ...), or
// take its whole message to compare.
#pragma once

#include <gtest/gtest.h>

#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "src/core/error.hpp"

namespace hydrocoef::test {

inline void expect_input_error(const std::function<void()>& action, const std::vector<std::string>& expected) {
  try {
    action();
    ADD_FAILURE() << "expected an InputError mentioning '" << expected.front() << "'";
  } catch (const InputError& error) {
    const std::string message = error.what();
    for (const auto& piece : expected)
      EXPECT_NE(message.find(piece), std::string::npos) << "message '" << message << "' lacks '" << piece << "'";
  }
}

/// The message of the InputError `action` throws; fails the test if it throws
/// nothing or another exception.
inline std::string input_error_message(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  } catch (const std::exception& error) {
    ADD_FAILURE() << "threw a non-InputError: " << error.what();
    return {};
  }
  ADD_FAILURE() << "did not throw";
  return {};
}

}  // namespace hydrocoef::test
