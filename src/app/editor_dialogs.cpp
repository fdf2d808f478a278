#include "app/editor_dialogs.h"

#include <imgui.h>

#include <algorithm>
#include <functional>
#include <string>
#include <system_error>
#include <vector>

#include "app/editor.h"
#include "io/formats/mesh_format.h"

namespace app {
namespace {

const char* browser_title(FileBrowser::Purpose purpose) {
    switch (purpose) {
        case FileBrowser::Purpose::Open: return "Open a mesh";
        case FileBrowser::Purpose::SaveAs: return "Save the mesh as";
        case FileBrowser::Purpose::SaveStrokes: return "Save the strokes as a script";
        case FileBrowser::Purpose::ExportLods: return "Export the LODs as";
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
        if (!is_folder && purpose != FileBrowser::Purpose::SaveStrokes && !rgbio::has_mesh_extension(item.path().string()))
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
        case FileBrowser::Purpose::ExportLods: editor.start_lod_export(path); break;
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
    // Answered: closed now, or the modal would stay open unseen and keep the keyboard and mouse.
    if (pressed != nullptr) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    if (pressed != nullptr) pressed->act();
}

// While the cage of a dense mesh is made: its phase and progress, and Stop.
void remesh_progress(Editor& editor) {
    const BackgroundTask* task = editor.file_task();
    const char* title = "Making a cage";
    if (task == nullptr || task->kind() != BackgroundTask::Kind::Remesh) {
        // Done or stopped: closed, or the modal would stay open unseen and keep the keyboard and mouse.
        if (ImGui::IsPopupOpen(title) && ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
            ImGui::CloseCurrentPopup();
            ImGui::EndPopup();
        }
        return;
    }
    ImGui::OpenPopup(title);
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::Text("Making a cage of %zu triangles for %s", editor.cage_triangles(), task->path().c_str());
    ImGui::Text("%s", task->phase().c_str());
    ImGui::ProgressBar(static_cast<float>(task->fraction()), ImVec2(420.0f, 0.0f));
    const bool stop = ImGui::Button("Stop") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
    ImGui::SameLine();
    ImGui::TextDisabled("Esc; the mesh on screen stays as it is");
    ImGui::EndPopup();
    if (stop) editor.stop_remesh();
}

// A dense plain mesh was read: a cage that keeps its detail, or the mesh as a base mesh.
void dense_mesh_question(Editor& editor) {
    const char* title = "A dense mesh";
    ImGui::OpenPopup(title);
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::Text("%s has %zu triangles.", editor.pending_path().c_str(), editor.dense_triangles());
    ImGui::TextUnformatted(
        "A cage keeps its detail: the brush then paints level of detail of this mesh,\n"
        "coarsening below the file and refining back to its detail. As a base mesh,\n"
        "every triangle is a level-0 face and the brush refines it further.");
    std::size_t& cage = editor.cage_triangles();
    const std::size_t smallest = editor.smallest_cage_triangles();
    const std::size_t most = std::max(editor.dense_triangles(), smallest);
    ImGui::SetNextItemWidth(160.0f);
    static_assert(sizeof(std::size_t) == 8, "ImGuiDataType_U64 edits the count in place");
    ImGui::InputScalar("cage triangles", ImGuiDataType_U64, &cage);
    cage = std::clamp(cage, smallest, most);
    ImGui::SameLine();
    ImGui::TextDisabled("(at least %zu for its topology)", smallest);
    const std::string make = "Make a cage of " + std::to_string(cage) + " triangles and keep the detail";
    const bool make_cage = ImGui::Button(make.c_str());
    const bool as_base = ImGui::Button("Open it as a base mesh");
    ImGui::SameLine();
    // Esc: the window gives the editor no keys while a modal is open.
    const bool cancel = ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
    if (make_cage || as_base || cancel) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    if (make_cage) editor.answer_dense_mesh(true);
    else if (as_base) editor.answer_dense_mesh(false);
    else if (cancel) editor.answer_pending(false);
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
    // Esc: the window gives the editor no keys while a modal is open.
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) browser.purpose = FileBrowser::Purpose::None;
    if (browser.purpose == FileBrowser::Purpose::None) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

void questions(Editor& editor) {
    const auto yes = [&] { editor.answer_pending(true); };
    const auto no = [&] { editor.answer_pending(false); };
    switch (editor.pending()) {
        case Pending::None: remesh_progress(editor); return;
        case Pending::DenseMesh: dense_mesh_question(editor); return;
        case Pending::RemeshFailed: ask("No cage", editor.pending_message(), {{"OK", no}}); return;
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
