#include "app/editor_dialogs.h"

#include <imgui.h>

#include <algorithm>
#include <functional>
#include <string>
#include <system_error>
#include <vector>

#include "app/editor.h"

namespace app {
namespace {

const char* browser_title(FileBrowser::Purpose purpose) {
    switch (purpose) {
        case FileBrowser::Purpose::Open: return "Open a mesh";
        case FileBrowser::Purpose::SaveAs: return "Save the mesh as";
        case FileBrowser::Purpose::SaveStrokes: return "Save the strokes as a script";
        case FileBrowser::Purpose::None: break;
    }
    return "";
}

struct Entry {
    std::string name;
    bool folder;
};

// Folders first, then the files the purpose can use (meshes to open; anything to save over), by name.
std::vector<Entry> listing(const std::filesystem::path& folder, FileBrowser::Purpose purpose) {
    std::vector<Entry> entries;
    std::error_code error;
    for (const auto& item : std::filesystem::directory_iterator(folder, std::filesystem::directory_options::skip_permission_denied, error)) {
        const std::string name = item.path().filename().string();
        if (name.starts_with('.')) continue;
        std::error_code kind_error;
        const bool is_folder = item.is_directory(kind_error);
        if (!is_folder && purpose != FileBrowser::Purpose::SaveStrokes && item.path().extension() != ".obj" && item.path().extension() != ".OBJ")
            continue;
        entries.push_back({name, is_folder});
    }
    std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.folder != b.folder ? a.folder : a.name < b.name; });
    return entries;
}

void set_name(FileBrowser& browser, const std::string& name) {
    const std::size_t n = std::min(name.size(), browser.name.size() - 1);
    std::copy_n(name.begin(), n, browser.name.begin());
    browser.name[n] = '\0';
}

void finish(Editor& editor, FileBrowser& browser) {
    const std::string path = (browser.folder / browser.name.data()).string();
    switch (browser.purpose) {
        case FileBrowser::Purpose::Open: editor.request_open(path); break;
        case FileBrowser::Purpose::SaveAs: editor.request_save_as(path); break;
        case FileBrowser::Purpose::SaveStrokes: editor.save_strokes(path); break;
        case FileBrowser::Purpose::None: break;
    }
    browser.purpose = FileBrowser::Purpose::None;
}

struct Answer {
    const char* button;
    std::function<void()> act;
};

// A modal question and what each of its buttons does.
void ask(const char* title, const std::string& text, const std::vector<Answer>& answers) {
    ImGui::OpenPopup(title);
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::TextUnformatted(text.c_str());
    const Answer* pressed = nullptr;
    for (const Answer& answer : answers) {
        if (&answer != &answers.front()) ImGui::SameLine();
        if (ImGui::Button(answer.button)) pressed = &answer;
    }
    ImGui::EndPopup();
    if (pressed != nullptr) pressed->act();
}

}  // namespace

void open_browser(PanelState& state, FileBrowser::Purpose purpose, const char* current) {
    FileBrowser& browser = state.browser;
    browser.purpose = purpose;
    const std::filesystem::path path(current);
    std::error_code error;
    browser.folder = path.has_parent_path() && std::filesystem::is_directory(path.parent_path(), error)
                         ? std::filesystem::absolute(path.parent_path(), error)
                         : std::filesystem::current_path(error);
    set_name(browser, purpose == FileBrowser::Purpose::SaveStrokes ? path.stem().string() + ".lod" : path.filename().string());
}

void file_browser(Editor& editor, FileBrowser& browser) {
    if (browser.purpose == FileBrowser::Purpose::None) return;
    const char* title = browser_title(browser.purpose);
    ImGui::OpenPopup(title);
    ImGui::SetNextWindowSize(ImVec2(560.0f, 440.0f), ImGuiCond_Appearing);
    if (!ImGui::BeginPopupModal(title, nullptr)) return;
    ImGui::TextWrapped("%s", browser.folder.string().c_str());
    if (ImGui::BeginChild("##entries", ImVec2(0.0f, -2.0f * ImGui::GetFrameHeightWithSpacing()), true)) {
        if (browser.folder.has_parent_path() && browser.folder != browser.folder.root_path() && ImGui::Selectable("../"))
            browser.folder = browser.folder.parent_path();
        for (const Entry& entry : listing(browser.folder, browser.purpose)) {
            const std::string label = entry.folder ? entry.name + "/" : entry.name;
            if (!ImGui::Selectable(label.c_str(), !entry.folder && entry.name == browser.name.data(), ImGuiSelectableFlags_AllowDoubleClick))
                continue;
            if (entry.folder) {
                browser.folder /= entry.name;
                break;  // the listing changed under the loop
            }
            set_name(browser, entry.name);
            if (ImGui::IsMouseDoubleClicked(0)) finish(editor, browser);
        }
    }
    ImGui::EndChild();
    // The name has the keyboard from the start, and Enter anywhere in the dialog confirms.
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::InputText("name", browser.name.data(), browser.name.size());
    const bool entered = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter));
    const bool named = browser.name[0] != '\0';
    if ((ImGui::Button(browser.purpose == FileBrowser::Purpose::Open ? "Open" : "Save") || entered) && named) finish(editor, browser);
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) browser.purpose = FileBrowser::Purpose::None;
    if (browser.purpose == FileBrowser::Purpose::None) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

void questions(Editor& editor) {
    const auto yes = [&] { editor.answer_pending(true); };
    const auto no = [&] { editor.answer_pending(false); };
    switch (editor.pending()) {
        case Pending::None: return;
        case Pending::DiscardForQuit:
            ask("Quit?", "The mesh has unsaved changes.",
                {{"Save and quit", [&] { editor.save_and_quit(); }}, {"Quit without saving", yes}, {"Cancel", no}});
            return;
        case Pending::DiscardForOpen:
            ask("Open?", editor.pending_path() + " is read. Discard the unsaved changes and open it?", {{"Discard and open", yes}, {"Keep editing", no}});
            return;
        case Pending::Overwrite: ask("Overwrite?", editor.pending_path() + " exists. Replace it?", {{"Replace", yes}, {"Cancel", no}}); return;
        case Pending::Recover:
            ask("Recover?",
                "rgbsub did not exit cleanly while editing " +
                    (editor.pending_path().empty() ? std::string("an untitled mesh") : editor.pending_path()) + ".\nRecover the unsaved work?",
                {{"Recover", yes}, {"Discard it", no}});
            return;
    }
}

}  // namespace app
