// Test support: run an action that must throw InputError, and check that the
// message mentions each expected piece (file, line, the value found, ...).
#pragma once

#include <gtest/gtest.h>

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

}  // namespace hydrocoef::test
