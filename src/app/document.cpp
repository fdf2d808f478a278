#include "app/document.h"

#include <algorithm>
#include <filesystem>
#include <new>
#include <span>
#include <utility>

#include "app/display_pace.h"
#include "io/mesh_export.h"
#include "rgb/values/restore_state.h"

namespace app {

Document::Document() : changes_(std::make_unique<render::MeshChanges>(mesh_)) { resync(); }

Document::~Document() = default;

std::vector<std::string> Document::open(const std::string& path) {
    LoadedDocument loaded = load_document(path, geometry_.source());
    std::vector<std::string> warnings = std::move(loaded.warnings);
    adopt(std::move(loaded), path);
    return warnings;
}

void Document::adopt(LoadedDocument loaded, std::string path, bool dirty) {
    mesh_ = std::move(loaded.mesh);  // observers stay with the object
    attributes_ = std::move(loaded.attributes);
    changes_->clear();
    faces_caught_up_ = vertices_caught_up_ = 0;
    geometry_ = std::move(loaded.geometry);
    index_ = std::move(loaded.index);
    room_ = 0;
    keep_room(mesh_.num_faces());  // nothing to copy when the file's thread reserved it (load_document)
    uv_channel_ = std::move(loaded.uvs);
    uv_layout_.reset();
    display_changes_ = DisplayChanges{{}, true};
    start_history(std::move(path), dirty);
}

void Document::adopt(rgb::Mesh mesh, std::string path) {
    attributes_ = nullptr;
    geometry_.set_appearance(nullptr);
    replace_mesh(std::move(mesh));
    uv_channel_.reset();
    uv_layout_.reset();
    start_history(std::move(path), false);
}

void Document::start_history(std::string path, bool unsaved) {
    history_.clear();
    saved_position_ = history_.position();
    unsaved_setting_ = unsaved;
    start_file_ = unsaved ? std::string() : path;
    start_file_saved_over_ = false;
    path_ = std::move(path);
    ++changes_count_;
}

void Document::save(const std::string& path, const rgbio::SaveOptions& options) {
    rgbio::save_mesh_file(mesh_, path, with_attributes(options));
    if (!rgbio::is_export_path(path)) mark_saved(path);
}

void Document::mark_saved(const std::string& path) {
    path_ = path;
    saved_position_ = history_.position();
    unsaved_setting_ = false;
    start_file_saved_over_ = start_file_saved_over_ || path == start_file_;
}

std::shared_ptr<const rgb::UvLayout> Document::uv_layout() {
    if (!uv_channel_) return nullptr;
    if (!uv_layout_ || uv_layout_base_ != mesh_.base().serial()) {
        uv_layout_ = std::make_shared<const rgb::UvLayout>(mesh_.base(), *uv_channel_);
        uv_layout_base_ = mesh_.base().serial();
    }
    return uv_layout_;
}

std::optional<rgb::UvInterpolation> Document::uv_interpolation() const {
    if (!uv_channel_) return std::nullopt;
    return uv_channel_->interpolation;
}

void Document::set_uv_interpolation(rgb::UvInterpolation interpolation) {
    if (!uv_channel_ || uv_channel_->interpolation == interpolation) return;
    uv_channel_->interpolation = interpolation;
    uv_layout_.reset();
    unsaved_setting_ = true;
    ++changes_count_;
    // The display shows the UVs the option gives.
    if (const auto& shown = geometry_.appearance(); shown && shown->uvs) {
        auto look = std::make_shared<render::SurfaceAppearance>(*shown);
        look->uvs->interpolation = interpolation;
        geometry_.set_appearance(std::move(look));
        resync();
    }
}

rgbio::SaveOptions Document::with_attributes(rgbio::SaveOptions options) {
    options.attributes = attributes_;
    options.uvs = uv_layout();
    return options;
}

void Document::saved_as(const std::string& path, const SaveMark& mark) {
    const bool setting_changed_since = unsaved_setting_ && mark.changes != changes_count_;
    mark_saved(path);
    saved_position_ = mark.position;
    unsaved_setting_ = setting_changed_since;
}

void Document::begin_edit(std::string label) {
    keep_room_for_edit();
    history_.begin_edit(std::move(label));
}

void Document::keep_room(std::size_t faces) {
    if (faces <= room_) return;
    try {
        app::reserve_room(mesh_, geometry_, index_, kRoomFactor * faces);
        room_ = kRoomFactor * faces;
    } catch (const std::bad_alloc&) {
        // No room now: the arrays grow as the work goes, and work stops cleanly if memory runs out.
    }
}

void Document::keep_room_for_edit() { keep_room(mesh_.num_faces() + mesh_.num_faces() / 4); }

void Document::end_edit(bool changed, std::optional<std::string> script, std::optional<std::string> label) {
    history_.end_edit(changed, std::move(script), std::move(label));
    changes_count_ += changed;
}

bool Document::abandon_edit() { return history_.abandon_edit(); }

bool Document::begin_undo() { return begin_crossing(&UndoHistory::begin_undo); }

bool Document::begin_redo() { return begin_crossing(&UndoHistory::begin_redo); }

bool Document::begin_crossing(bool (UndoHistory::*begin)()) {
    keep_room_for_edit();
    const std::uint64_t base = mesh_.base().serial();
    if (!(history_.*begin)()) return false;
    ++changes_count_;
    // A retag moved every vertex without telling the observers.
    if (mesh_.base().serial() != base) resync();
    return true;
}

void Document::set_sharp_features(const rgb::SharpFeatures& features, std::string label) {
    history_.retag(std::move(label), features);
    ++changes_count_;
    resync();
}

const render::SurfaceGeometry& Document::geometry() {
    while (!catch_up_part()) {
    }
    return geometry_;
}

bool Document::catch_up_display(std::chrono::microseconds budget, const DisplayPace& pace) {
    const auto deadline = std::chrono::steady_clock::now() + budget;
    for (bool first = true;; first = false) {
        const double left_us = std::chrono::duration<double, std::micro>(deadline - std::chrono::steady_clock::now()).count();
        const std::size_t fits = std::min(kDisplayPartFaces, pace.faces_within(left_us));
        if (!first && fits < kMinDisplayPartFaces) return false;
        if (catch_up_part(std::max(fits, kMinDisplayPartFaces))) return true;
    }
}

std::size_t Document::display_backlog() const {
    return changes_->everything() ? mesh_.face_capacity() : changes_->changed_faces().size() - faces_caught_up_;
}

bool Document::display_behind() const {
    return changes_->everything() || changes_->changed_faces().size() - faces_caught_up_ > kDisplayPartFaces;
}

bool Document::display_up_to_date() const {
    return changes_->empty() && !display_changes_.rebuilt && display_changes_.ranges.empty();
}

bool Document::catch_up_part(std::size_t max_faces) {
    if (changes_->empty()) return true;
    const auto start = std::chrono::steady_clock::now();
    const std::size_t faces_before = faces_caught_up_, vertices_before = vertices_caught_up_;
    std::vector<render::SlotRange> ranges;
    const std::span<const rgb::FaceId> faces = changes_->changed_faces();
    const std::span<const rgb::VertexId> vertices = changes_->moved_vertices();
    if (changes_->everything()) {
        ranges = geometry_.update(mesh_, *changes_);
        faces_caught_up_ = faces.size();
        vertices_caught_up_ = vertices.size();
    } else {
        // The moved vertices in the same proportion as the faces (each added face lists its three).
        const std::size_t face_end = std::min(faces.size(), faces_caught_up_ + max_faces);
        const std::size_t vertex_end =
            face_end == faces.size() ? vertices.size()
                                     : std::max(vertices_caught_up_, std::min(vertices.size(), vertices.size() * face_end / faces.size()));
        ranges = geometry_.update_part(mesh_, faces.subspan(faces_caught_up_, face_end - faces_caught_up_),
                                  vertices.subspan(vertices_caught_up_, vertex_end - vertices_caught_up_));
        faces_caught_up_ = face_end;
        vertices_caught_up_ = vertex_end;
    }
    const auto indexing = std::chrono::steady_clock::now();
    index_.update(geometry_, ranges);
    catch_up_timing_.geometry_ms += std::chrono::duration<double, std::milli>(indexing - start).count();
    catch_up_timing_.index_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - indexing).count();
    ++catch_up_timing_.parts;
    catch_up_timing_.faces += faces_caught_up_ - faces_before;
    catch_up_timing_.vertices += vertices_caught_up_ - vertices_before;
    if (!display_changes_.rebuilt) display_changes_.ranges.insert(display_changes_.ranges.end(), ranges.begin(), ranges.end());
    if (faces_caught_up_ < faces.size() || vertices_caught_up_ < vertices.size()) return false;
    changes_->clear();
    faces_caught_up_ = vertices_caught_up_ = 0;
    return true;
}

void Document::set_position_source(render::PositionSource source) {
    if (geometry_.source() == source) return;
    geometry_.set_source(source);
    resync();
}

void Document::set_detail_distance(bool on) {
    if (geometry_.detail_distance() == on) return;
    geometry_.set_detail_distance(on);
    resync();
}

Document::DisplayChanges Document::take_display_changes() {
    DisplayChanges taken = std::exchange(display_changes_, DisplayChanges{});
    // Several updates since the last take: one sorted, coalesced list.
    std::sort(taken.ranges.begin(), taken.ranges.end(), [](const render::SlotRange& a, const render::SlotRange& b) { return a.first < b.first; });
    std::vector<render::SlotRange> merged;
    for (const render::SlotRange& r : taken.ranges) {
        if (!merged.empty() && r.first <= merged.back().first + merged.back().count)
            merged.back().count = std::max(merged.back().count, r.first + r.count - merged.back().first);
        else
            merged.push_back(r);
    }
    taken.ranges = std::move(merged);
    return taken;
}

std::optional<SurfaceHit> Document::pick(const Ray& ray) { return index_.pick(geometry(), ray); }

void Document::replace_mesh(rgb::Mesh mesh) {
    mesh_ = std::move(mesh);  // observers stay with the object
    room_ = 0;
    keep_room(mesh_.num_faces());
    resync();
}

void Document::resync() {
    changes_->clear();
    faces_caught_up_ = vertices_caught_up_ = 0;
    geometry_.rebuild(mesh_);
    index_.rebuild(mesh_, geometry_);
    display_changes_ = DisplayChanges{{}, true};
}

std::string document_title(const Document& document) {
    const std::string name =
        document.path().empty() ? std::string("untitled") : std::filesystem::path(document.path()).filename().string();
    return document.dirty() ? name + "*" : name;
}

}  // namespace app
