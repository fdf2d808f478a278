#pragma once
// A fresh folder under the system's temporary directory for one test, named after the test and the
// process, removed again when the test ends.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

namespace rgbio::test {

class TempFolderTest : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = std::filesystem::temp_directory_path() / ("rgbsub_" + std::to_string(::getpid()) + "_" +
                                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(folder_);
        std::filesystem::create_directories(folder_);
    }
    void TearDown() override { std::filesystem::remove_all(folder_); }
    std::string path(const std::filesystem::path& name) const { return (folder_ / name).string(); }
    void write(const std::filesystem::path& name, const std::string& text) const {
        std::ofstream(folder_ / name, std::ios::binary) << text;
    }
    std::filesystem::path folder_;
};

}  // namespace rgbio::test
