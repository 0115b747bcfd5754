#pragma once
// A fixture with a fresh directory of its own under the system's temporary
// directory, removed with everything in it after each test.

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>

namespace facet::testing {

class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("facet_test_" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path dir_;
};

}  // namespace facet::testing
