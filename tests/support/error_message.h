// What a test expects of a failure: the message of what a call throws, and a check that it
// throws an E whose message names the problem (std only: for the tests of every library).
#pragma once
#include <gtest/gtest.h>

#include <exception>
#include <string>

namespace hylios::test {

/// The message of the E that `run` throws ("" when it throws none; another exception propagates).
template <typename E = std::exception, typename Run>
std::string errorOf(const Run& run) {
  try {
    run();
  } catch (const E& e) {
    return e.what();
  }
  return "";
}

/// Expects run() to throw an E whose message contains `needle`.
template <typename E = std::exception, typename Run>
void expectThrowMentioning(const Run& run, const std::string& needle) {
  try {
    run();
    ADD_FAILURE() << "no exception; expected one mentioning '" << needle << "'";
  } catch (const E& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

}  // namespace hylios::test
