#include "app/document.h"

#include <filesystem>
#include <utility>

#include "rgb/state.h"

namespace app {

Document::Document() : changes_(std::make_unique<render::MeshChanges>(mesh_)) { geometry_.rebuild(mesh_); }

Document::~Document() = default;

std::vector<std::string> Document::open(const std::string& path) {
    std::vector<std::string> warnings;
    rgb::Mesh loaded = rgbio::load_mesh(path, &warnings);
    adopt(std::move(loaded), path);
    dirty_ = false;
    return warnings;
}

void Document::adopt(rgb::Mesh mesh, std::string path) {
    replace_mesh(std::move(mesh));
    path_ = std::move(path);
    history_.clear();
    dirty_ = false;
}

void Document::save(const std::string& path, const rgbio::SaveOptions& options) {
    rgbio::save_mesh(mesh_, path, options);
    path_ = path;
    dirty_ = false;
}

void Document::begin_edit(std::string label) { history_.begin_edit(mesh_, std::move(label)); }

void Document::end_edit(bool changed) {
    history_.end_edit(mesh_, changed);
    dirty_ = dirty_ || changed;
}

bool Document::abandon_edit() {
    std::optional<rgb::Mesh> before = history_.abandon_edit();
    if (!before) return false;
    replace_mesh(std::move(*before));
    return true;
}

bool Document::undo() {
    std::optional<rgb::Mesh> before = history_.undo(mesh_);
    if (!before) return false;
    replace_mesh(std::move(*before));
    dirty_ = true;
    return true;
}

bool Document::redo() {
    std::optional<rgb::Mesh> after = history_.redo(mesh_);
    if (!after) return false;
    replace_mesh(std::move(*after));
    dirty_ = true;
    return true;
}

void Document::set_sharp_features(const rgb::SharpFeatures& features, std::string label) {
    rgb::Mesh retagged = rgb::with_sharp_features(mesh_, features);
    begin_edit(std::move(label));
    replace_mesh(std::move(retagged));
    end_edit(true);
}

const render::SurfaceGeometry& Document::geometry() {
    if (!changes_->empty()) {
        geometry_.update(mesh_, *changes_);
        changes_->clear();
    }
    return geometry_;
}

void Document::replace_mesh(rgb::Mesh mesh) {
    changes_.reset();  // unregisters from the outgoing mesh
    mesh_ = std::move(mesh);
    changes_ = std::make_unique<render::MeshChanges>(mesh_);
    geometry_.rebuild(mesh_);
    ++generation_;
}

std::string document_title(const Document& document) {
    const std::string name =
        document.path().empty() ? std::string("untitled") : std::filesystem::path(document.path()).filename().string();
    return document.dirty() ? name + "*" : name;
}

}  // namespace app
