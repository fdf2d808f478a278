#pragma once
// Where the editor tests find the project's assets and put the files they write.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace app::test {

// Built as a path, not by string concatenation: from a short source folder (/tmp/wt/h2) GCC 12 takes
// the concatenation's inlined copy for an overflow of the short-string buffer (-Wstringop-overflow).
inline std::string asset_path(const std::string& name) { return (std::filesystem::path(RGBSUB_SOURCE_DIR) / "assets" / name).string(); }

inline std::string bunny_path() { return asset_path("bunny.obj"); }

// An empty folder of that name under the test's temporary directory.
inline std::filesystem::path fresh_folder(const std::string& name) {
    const std::filesystem::path folder = std::filesystem::path(::testing::TempDir()) / name;
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

}  // namespace app::test
