// Settings that last between sessions (editor_settings.h): each test has its own XDG_CONFIG_HOME,
// so nothing reads or writes the user's own settings.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/editor.h"
#include "app/editor_settings.h"
#include "io/script/lod_script.h"
#include "test_paths.h"

namespace app::test {
namespace {

using namespace std::string_literals;

class EditorSettingsTest : public ::testing::Test {
protected:
    void SetUp() override {
        const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
        config_ = fresh_folder(std::string("settings_") + info->name());
        if (const char* saved = std::getenv("XDG_CONFIG_HOME")) saved_ = saved;
        ::setenv("XDG_CONFIG_HOME", config_.c_str(), 1);
    }
    void TearDown() override {
        if (saved_) ::setenv("XDG_CONFIG_HOME", saved_->c_str(), 1);
        else ::unsetenv("XDG_CONFIG_HOME");
    }
    std::filesystem::path file() const { return settings_file(*settings_folder()); }
    void write(const std::string& text) const {
        std::filesystem::create_directories(file().parent_path());
        std::ofstream(file(), std::ios::binary) << text;
    }

    std::filesystem::path config_;
    std::optional<std::string> saved_;
};

TEST_F(EditorSettingsTest, LiveInXdgConfigHomeOrHomeConfig) {
    EXPECT_EQ(settings_folder(), config_ / "rgbsub");
    EXPECT_EQ(file(), config_ / "rgbsub" / "settings.txt");
    const std::filesystem::path fallback = std::filesystem::path(std::getenv("HOME")) / ".config/rgbsub";
    ::setenv("XDG_CONFIG_HOME", "relative/config", 1);  // the XDG spec: only an absolute path counts
    EXPECT_EQ(settings_folder(), fallback);
    ::unsetenv("XDG_CONFIG_HOME");
    EXPECT_EQ(settings_folder(), fallback);
}

// One session changes the brush through its keys, opens files and switches the projection; the
// next one starts with all of it, and the display, panel and window size come back as they were.
TEST_F(EditorSettingsTest, AreKeptBetweenSessions) {
    EditorSettings stored;
    {
        Editor first(glm::ivec2(800, 600));
        for (const char* name : {"bunny.obj", "default.obj"}) ASSERT_TRUE(first.open(asset_path(name))) << first.message();
        for (Key key : {Key::RightBracket, Key::RightBracket, Key::Equal, Key::Digit3, Key::Keypad5}) first.key_pressed(key, {});
        first.brush().mirror = rgbio::kMirrorX | rgbio::kMirrorZ;
        first.brush().falloff = 0.3f;
        first.brush().dabs_per_radius = 7.5f;
        first.brush().lazy_px = 25.0f;
        take_settings(first, stored);
        stored.display.colouring = render::Colouring::Level;
        stored.display.wireframe = false;
        stored.display.limit_positions = true;
        stored.panel.panel_open = false;
        stored.panel.sections = {{"Brush", false}, {"Statistics", true}, {"Detail by size, accuracy, view", false}};
        stored.window_size = {1600, 900};
        store_settings(file(), stored);
    }
    const LoadedSettings loaded = load_settings(file());
    EXPECT_FALSE(loaded.warning) << *loaded.warning;
    EXPECT_EQ(loaded.settings, stored) << format_settings(loaded.settings);

    Editor second(glm::ivec2(800, 600));
    apply_settings(second, loaded.settings);
    EXPECT_EQ(second.brush().mode, BrushMode::Set);
    EXPECT_EQ(second.brush().target_level, BrushSettings().target_level + 1);
    EXPECT_FLOAT_EQ(second.brush().radius_px, BrushSettings().radius_px * 1.1f * 1.1f);
    EXPECT_EQ(second.brush(), stored.brush);
    const std::vector<std::string> recent{std::filesystem::path(asset_path("default.obj")).lexically_normal().string(),
                                          std::filesystem::path(asset_path("bunny.obj")).lexically_normal().string()};
    EXPECT_EQ(second.recent_files(), recent);
    EXPECT_TRUE(second.camera().camera().orthographic);
    ASSERT_TRUE(second.open(asset_path("bunny.obj")));
    EXPECT_TRUE(second.camera().camera().orthographic) << "opening a file keeps the projection chosen";
}

// No file yet: the defaults, quietly; the defaults show the topology (wireframe over shading).
TEST_F(EditorSettingsTest, AMissingFileGivesTheDefaults) {
    const LoadedSettings loaded = load_settings(file());
    EXPECT_FALSE(loaded.warning);
    EXPECT_EQ(loaded.settings, EditorSettings());
    EXPECT_TRUE(loaded.settings.display.wireframe);
    EXPECT_TRUE(loaded.settings.recent_files.empty());
}

// Every kind of damage: the whole file is ignored (the defaults), with a warning naming the file,
// the line and the problem; nothing throws.
TEST_F(EditorSettingsTest, ADamagedFileIsIgnoredWithAWarning) {
    struct Damage {
        std::string text, line_and_problem;
    };
    const std::vector<Damage> damages{
        {"brush.level = 4\nthis is not a setting\n", ":2: expected 'key = value'"},
        {"brush.level = 4\nbrush.colour = red\n", ":2: unknown key 'brush.colour'"},
        {"brush.level = 99\n", ":1: '99' is not a value brush.level takes"},
        {"# comment\nbrush.radius_px = nan\n", ":2: 'nan' is not a value brush.radius_px takes"},
        {"brush.radius_px = 40px\n", ":1: '40px' is not a value"},
        {"display.wireframe = yes\n", ":1: 'yes' is not a value display.wireframe takes"},
        {"display.colouring = sepia\n", ":1: 'sepia' is not a value"},
        {"window.width = 100000\n", ":1: '100000' is not a value window.width takes"},
        {"panel.section.Brush = 1\n", ":1: panel.section.Brush must be true or false"},
        {"recent =\n", ":1: an empty recent file"},
        {"brush.level = 4\n\x89PNG\r\n\x1a\n\0\0"s, ":2: expected 'key = value'"},
    };
    for (const Damage& damage : damages) {
        write(damage.text);
        const LoadedSettings loaded = load_settings(file());
        ASSERT_TRUE(loaded.warning) << damage.text;
        EXPECT_NE(loaded.warning->find(file().string() + damage.line_and_problem), std::string::npos) << *loaded.warning;
        EXPECT_NE(loaded.warning->find("ignored"), std::string::npos) << *loaded.warning;
        EXPECT_EQ(loaded.settings, EditorSettings()) << damage.text;
    }
    // A folder where the file should be cannot be read: the same.
    std::filesystem::remove(file());
    std::filesystem::create_directories(file());
    const LoadedSettings folder = load_settings(file());
    ASSERT_TRUE(folder.warning);
    EXPECT_EQ(folder.settings, EditorSettings());
}

// The file is replaced whole, with nothing left beside it; keys left out keep their defaults, and
// values that cannot be written on one line are left out.
TEST_F(EditorSettingsTest, AreWrittenAtomically) {
    write("brush.level = 5\n");
    EditorSettings settings;
    settings.brush.target_level = 7;
    settings.recent_files = {"/models/a.obj", "/models/two\nlines.obj", " /padded.obj"};
    store_settings(file(), settings);
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(file().parent_path())) names.push_back(entry.path().filename().string());
    EXPECT_EQ(names, std::vector<std::string>{"settings.txt"});
    const LoadedSettings loaded = load_settings(file());
    ASSERT_FALSE(loaded.warning) << *loaded.warning;
    EXPECT_EQ(loaded.settings.brush.target_level, 7);
    EXPECT_EQ(loaded.settings.recent_files, std::vector<std::string>{"/models/a.obj"});

    write("display.colouring = rgb\n");
    EXPECT_EQ(load_settings(file()).settings.display.colouring, render::Colouring::RgbType);
    EXPECT_EQ(load_settings(file()).settings.brush, BrushSettings()) << "keys left out keep their defaults";

    // Where no file can be written (the folder's name taken by a file), store says so by throwing:
    // the window reports it and goes on.
    std::filesystem::remove_all(file().parent_path());
    std::ofstream(file().parent_path()) << "in the way\n";
    EXPECT_ANY_THROW(store_settings(file(), settings));
    std::filesystem::remove(file().parent_path());
}

}  // namespace
}  // namespace app::test
