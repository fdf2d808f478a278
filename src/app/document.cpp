#include "app/document.h"

#include <filesystem>
#include <utility>

namespace app {

Document::Document() : changes_(std::make_unique<render::MeshChanges>(mesh_)) { resync(); }

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

void Document::begin_edit(std::string label) { history_.begin_edit(std::move(label)); }

void Document::end_edit(bool changed, std::optional<std::string> script) {
    history_.end_edit(changed, std::move(script));
    dirty_ = dirty_ || changed;
}

bool Document::abandon_edit() { return history_.abandon_edit(); }

bool Document::undo() {
    if (!history_.undo()) return false;
    dirty_ = true;
    return true;
}

bool Document::redo() {
    if (!history_.redo()) return false;
    dirty_ = true;
    return true;
}

const render::SurfaceGeometry& Document::geometry() {
    if (!changes_->empty()) {
        index_.update(geometry_, geometry_.update(mesh_, *changes_));
        changes_->clear();
    }
    return geometry_;
}

std::optional<SurfaceHit> Document::pick(const Ray& ray) { return index_.pick(geometry(), ray); }

void Document::replace_mesh(rgb::Mesh mesh) {
    mesh_ = std::move(mesh);  // observers stay with the object
    resync();
}

void Document::resync() {
    changes_->clear();
    geometry_.rebuild(mesh_);
    index_.rebuild(mesh_, geometry_);
    ++generation_;
}

std::string document_title(const Document& document) {
    const std::string name =
        document.path().empty() ? std::string("untitled") : std::filesystem::path(document.path()).filename().string();
    return document.dirty() ? name + "*" : name;
}

}  // namespace app
