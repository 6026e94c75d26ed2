// Runs the sph command built with the tests (SPH_BINARY) and collects its exit code and output.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace sph::testing {

struct CommandResult {
  int code;
  std::string output;  // stdout and stderr together
};

// One log per test (`logPrefix` + the test's name): ctest runs tests in parallel processes.
inline CommandResult runSph(const std::string& arguments, const std::string& logPrefix) {
  const std::filesystem::path log =
      std::filesystem::path(::testing::TempDir()) /
      (logPrefix + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
       ".log");
  const std::string command =
      std::string(SPH_BINARY) + " " + arguments + " > " + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

}  // namespace sph::testing
