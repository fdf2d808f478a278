#pragma once
// The editor's settings that last between sessions: the recent files, the brush, the display mode,
// the side panel's layout and the window's size, in $XDG_CONFIG_HOME/rgbsub/settings.txt (or
// ~/.config/rgbsub), a text file of `key = value` lines (docs/files.md "Editor settings"). A
// damaged file is ignored with a warning, never fatal; a write replaces the file atomically. Only
// the window reads and writes them: `edit --screenshot` and the tests' editors start from the
// defaults, so that their frames stay reproducible. GL-free.
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "app/brush.h"
#include "render/renderer.h"

namespace app {

class Editor;

// What the Display panel shows. The default shows the topology (wireframe over shading), so that a
// first stroke is visible at once.
struct DisplaySettings {
    render::Shading shading = render::Shading::Smooth;
    render::Colouring colouring = render::Colouring::Plain;
    bool wireframe = true;
    bool base_mesh = false;
    bool limit_positions = false;
    bool orthographic = false;
    bool operator==(const DisplaySettings&) const = default;
};

// The side panel: open or collapsed, and which of its sections are open (by their headers' names;
// a section not named keeps its default).
struct PanelLayout {
    bool panel_open = true;
    std::map<std::string, bool> sections;
    bool operator==(const PanelLayout&) const = default;
};

// The window sizes the settings keep (smaller or larger ones are a damaged file).
inline constexpr int kLeastWindowSide = 200;
inline constexpr int kMostWindowSide = 16384;

struct EditorSettings {
    std::vector<std::string> recent_files;  // newest first
    BrushSettings brush;
    DisplaySettings display;
    PanelLayout panel;
    glm::ivec2 window_size{1280, 800};
    bool operator==(const EditorSettings&) const = default;
};

// A settings text that cannot be read: "FILE:LINE: problem".
class SettingsError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// $XDG_CONFIG_HOME/rgbsub (an absolute XDG_CONFIG_HOME only, as the XDG spec asks), or
// ~/.config/rgbsub; none without either variable.
std::optional<std::filesystem::path> settings_folder();
std::filesystem::path settings_file(const std::filesystem::path& folder);

std::string format_settings(const EditorSettings& settings);
// Throws SettingsError naming `name`, the line and the problem: an unknown key, a value that does
// not parse or lies outside its range. Keys left out keep their defaults.
EditorSettings parse_settings(std::string_view text, const std::string& name);

struct LoadedSettings {
    EditorSettings settings;
    std::optional<std::string> warning;  // the file was damaged and is ignored: the defaults
};
// A missing file gives the defaults without a warning.
LoadedSettings load_settings(const std::filesystem::path& file);
// Makes the folder and replaces the file atomically. Throws rgbio::SaveError or
// std::filesystem::filesystem_error.
void store_settings(const std::filesystem::path& file, const EditorSettings& settings);

// The editor's share of the settings: the brush, the recent files and the projection.
void apply_settings(Editor& editor, const EditorSettings& settings);
void take_settings(const Editor& editor, EditorSettings& settings);

}  // namespace app
