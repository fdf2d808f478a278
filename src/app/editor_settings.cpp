#include "app/editor_settings.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <utility>

#include "app/editor.h"
#include "io/files/atomic_file.h"

namespace app {
namespace {

constexpr std::string_view kSettingsHeader = "# rgbsub editor settings: key = value; a damaged file is ignored, with a warning";
constexpr std::string_view kRecentKey = "recent";
constexpr std::string_view kSectionKey = "panel.section.";
constexpr std::string_view kIgnored = "; the settings file is ignored, the editor starts with its defaults";

// One `key = value` line: how it is written from the settings and read back into them (false: the
// value is not one this key takes).
struct SettingsField {
    std::string key;
    std::function<std::string(const EditorSettings&)> write;
    std::function<bool(EditorSettings&, std::string_view)> read;
};

std::string_view trimmed(std::string_view text) {
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

template <class T>
bool parse_number(std::string_view text, T& value) {
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc() && end == text.data() + text.size();
}

// `access` is a generic lambda giving the member of the settings, const or not.
template <class T, class Access>
SettingsField number(std::string key, Access access, T least, T most) {
    return {std::move(key),
            [access](const EditorSettings& s) {
                std::array<char, 32> text{};
                return std::string(text.data(), std::to_chars(text.data(), text.data() + text.size(), access(s)).ptr);
            },
            [access, least, most](EditorSettings& s, std::string_view text) {
                T value{};
                if (!parse_number(text, value) || !(value >= least && value <= most)) return false;
                access(s) = value;
                return true;
            }};
}

template <class Access>
SettingsField flag(std::string key, Access access) {
    return {std::move(key), [access](const EditorSettings& s) { return std::string(access(s) ? "true" : "false"); },
            [access](EditorSettings& s, std::string_view text) {
                if (text != "true" && text != "false") return false;
                access(s) = text == "true";
                return true;
            }};
}

template <class E, class Access>
SettingsField choice(std::string key, Access access, std::vector<std::pair<E, std::string_view>> names) {
    return {std::move(key),
            [access, names](const EditorSettings& s) {
                for (const auto& [value, name] : names)
                    if (value == access(s)) return std::string(name);
                return std::string(names.front().second);
            },
            [access, names](EditorSettings& s, std::string_view text) {
                for (const auto& [value, name] : names)
                    if (name == text) {
                        access(s) = value;
                        return true;
                    }
                return false;
            }};
}

const std::vector<SettingsField>& fields() {
    using T = BrushSettings::Target;
    using C = render::Colouring;
    static const std::vector<SettingsField> all{
        choice<BrushMode>("brush.mode", [](auto& s) -> auto& { return s.brush.mode; },
                          {{BrushMode::Refine, "refine"}, {BrushMode::Coarsen, "coarsen"}, {BrushMode::Set, "set"}}),
        choice<T>("brush.target", [](auto& s) -> auto& { return s.brush.target; },
                  {{T::Level, "level"}, {T::DetailSize, "detail-size"}, {T::Tolerance, "tolerance"}}),
        number<int>("brush.level", [](auto& s) -> auto& { return s.brush.target_level; }, 0, kMaxBrushLevel),
        choice<RadiusUnit>("brush.radius_unit", [](auto& s) -> auto& { return s.brush.unit; },
                           {{RadiusUnit::ScreenPixels, "px"}, {RadiusUnit::World, "world"}}),
        number<float>("brush.radius_px", [](auto& s) -> auto& { return s.brush.radius_px; }, kLeastRadiusPx, kMostRadiusPx),
        number<float>("brush.radius_world", [](auto& s) -> auto& { return s.brush.radius_world; }, 1e-6f, 1e6f),
        number<float>("brush.falloff", [](auto& s) -> auto& { return s.brush.falloff; }, 0.0f, 1.0f),
        flag("brush.paint_through", [](auto& s) -> auto& { return s.brush.paint_through; }),
        choice<RadiusUnit>("brush.detail_unit", [](auto& s) -> auto& { return s.brush.detail_unit; },
                           {{RadiusUnit::ScreenPixels, "px"}, {RadiusUnit::World, "world"}}),
        number<float>("brush.detail_px", [](auto& s) -> auto& { return s.brush.detail_px; }, 0.1f, 100.0f),
        number<float>("brush.detail_world", [](auto& s) -> auto& { return s.brush.detail_world; }, 1e-6f, 1e6f),
        number<std::uint8_t>("brush.mirror", [](auto& s) -> auto& { return s.brush.mirror; }, 0, 7),
        number<float>("brush.dabs_per_radius", [](auto& s) -> auto& { return s.brush.dabs_per_radius; }, kLeastDabsPerRadius,
                      kMostDabsPerRadius),
        number<float>("brush.lazy_px", [](auto& s) -> auto& { return s.brush.lazy_px; }, 0.0f, kMostLazyPx),
        choice<render::Shading>("display.shading", [](auto& s) -> auto& { return s.display.shading; },
                                {{render::Shading::Smooth, "smooth"}, {render::Shading::Flat, "flat"}}),
        choice<C>("display.colouring", [](auto& s) -> auto& { return s.display.colouring; },
                  {{C::Plain, "plain"}, {C::RgbType, "rgb"}, {C::Level, "level"}, {C::Material, "material"},
                   {C::VertexColour, "colours"}, {C::Checker, "checker"}, {C::Texture, "texture"},
                   {C::DetailDistance, "distance"}, {C::Matcap, "matcap"}}),
        flag("display.wireframe", [](auto& s) -> auto& { return s.display.wireframe; }),
        flag("display.base_mesh", [](auto& s) -> auto& { return s.display.base_mesh; }),
        flag("display.limit_positions", [](auto& s) -> auto& { return s.display.limit_positions; }),
        flag("display.orthographic", [](auto& s) -> auto& { return s.display.orthographic; }),
        flag("panel.open", [](auto& s) -> auto& { return s.panel.panel_open; }),
        number<int>("window.width", [](auto& s) -> auto& { return s.window_size.x; }, kLeastWindowSide, kMostWindowSide),
        number<int>("window.height", [](auto& s) -> auto& { return s.window_size.y; }, kLeastWindowSide, kMostWindowSide),
    };
    return all;
}

// A value written on one line and read back whole: no line breaks, no leading or trailing blanks.
bool fits_a_line(const std::string& value) {
    return !value.empty() && value.find_first_of("\r\n") == std::string::npos && trimmed(value) == value;
}

}  // namespace

std::optional<std::filesystem::path> settings_folder() {
    if (const char* config = std::getenv("XDG_CONFIG_HOME"); config != nullptr && *config == '/')
        return std::filesystem::path(config) / "rgbsub";
    if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') return std::filesystem::path(home) / ".config/rgbsub";
    return std::nullopt;
}

std::filesystem::path settings_file(const std::filesystem::path& folder) { return folder / "settings.txt"; }

std::string format_settings(const EditorSettings& settings) {
    std::string text = std::string(kSettingsHeader) + "\n";
    for (const SettingsField& field : fields()) text += field.key + " = " + field.write(settings) + "\n";
    for (const auto& [section, open] : settings.panel.sections)
        if (fits_a_line(section) && section.find('=') == std::string::npos)
            text += std::string(kSectionKey) + section + " = " + (open ? "true" : "false") + "\n";
    for (const std::string& recent : settings.recent_files)
        if (fits_a_line(recent)) text += std::string(kRecentKey) + " = " + recent + "\n";
    return text;
}

EditorSettings parse_settings(std::string_view text, const std::string& name) {
    EditorSettings settings;
    std::size_t line_number = 0;
    const auto fail = [&](const std::string& problem) {
        throw SettingsError(name + ":" + std::to_string(line_number) + ": " + problem);
    };
    while (!text.empty()) {
        ++line_number;
        const std::size_t end = std::min(text.find('\n'), text.size());
        const std::string_view line = trimmed(text.substr(0, end));
        text.remove_prefix(std::min(end + 1, text.size()));
        if (line.empty() || line.front() == '#') continue;
        const std::size_t equals = line.find('=');
        if (equals == std::string_view::npos) fail("expected 'key = value', got '" + std::string(line) + "'");
        const std::string key(trimmed(line.substr(0, equals)));
        const std::string_view value = trimmed(line.substr(equals + 1));
        if (key == kRecentKey) {
            if (value.empty()) fail("an empty recent file");
            settings.recent_files.emplace_back(value);
            continue;
        }
        if (key.starts_with(kSectionKey)) {
            if (value != "true" && value != "false") fail(key + " must be true or false, got '" + std::string(value) + "'");
            settings.panel.sections[key.substr(kSectionKey.size())] = value == "true";
            continue;
        }
        const auto field = std::find_if(fields().begin(), fields().end(), [&](const SettingsField& f) { return f.key == key; });
        if (field == fields().end()) fail("unknown key '" + key + "'");
        if (!field->read(settings, value)) fail("'" + std::string(value) + "' is not a value " + key + " takes");
    }
    if (settings.recent_files.size() > kMaxRecentFiles) settings.recent_files.resize(kMaxRecentFiles);
    return settings;
}

LoadedSettings load_settings(const std::filesystem::path& file) {
    std::error_code error;
    if (!std::filesystem::exists(file, error)) return {};
    if (!std::filesystem::is_regular_file(file, error))
        return {{}, file.string() + ": not a regular file" + std::string(kIgnored)};
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in.good() && !in.eof()) return {{}, file.string() + ": cannot be read" + std::string(kIgnored)};
    try {
        return {parse_settings(text.str(), file.string()), std::nullopt};
    } catch (const SettingsError& damaged) {
        return {{}, std::string(damaged.what()) + std::string(kIgnored)};
    }
}

void store_settings(const std::filesystem::path& file, const EditorSettings& settings) {
    std::filesystem::create_directories(file.parent_path());
    rgbio::write_file_atomically(file.string(), format_settings(settings));
}

void apply_settings(Editor& editor, const EditorSettings& settings) {
    editor.brush() = settings.brush;
    editor.set_recent_files(settings.recent_files);
    editor.camera().set_orthographic(settings.display.orthographic);
}

void take_settings(const Editor& editor, EditorSettings& settings) {
    settings.brush = editor.brush();
    settings.recent_files = editor.recent_files();
    settings.display.orthographic = editor.camera().camera().orthographic;
}

}  // namespace app
