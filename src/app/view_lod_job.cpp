#include "app/view_lod_job.h"

#include <utility>

namespace app {

namespace {

bool same_view(const rgb::ScreenView& a, const rgb::ScreenView& b) {
    return a.view_projection == b.view_projection && a.viewport == b.viewport && a.eye == b.eye;
}

}  // namespace

ViewLodJob::ViewLodJob(rgb::Mesh& mesh, const rgb::ViewLodSettings& settings, std::function<rgb::ScreenView()> current_view,
                       std::size_t max_face_changes)
    : current_view_(std::move(current_view)), view_(current_view_()), lod_(mesh, settings, view_), max_face_changes_(max_face_changes) {}

ViewLodJob::~ViewLodJob() = default;

bool ViewLodJob::step(std::chrono::microseconds slice) {
    if (frozen_) return false;
    // A new camera restarts the updater's pass; an unchanged one lets a settled mesh stay untouched.
    if (const rgb::ScreenView view = current_view_(); !same_view(view, view_)) {
        view_ = view;
        lod_.set_view(view_);
    }
    lod_.update(slice, max_face_changes_);
    return true;
}

float ViewLodJob::progress() const { return lod_.converged() ? 1.0f : 0.0f; }

bool ViewLodJob::changed() const { return lod_.stats().splits + lod_.stats().removals > 0; }

}  // namespace app
