// Brush benchmark: replays a recorded stroke (a wavy path across the view, one mouse sample per
// 5 px, one editor frame per sample) through the editor's input layer on the bunny refined
// uniformly, and reports what the editor costs at that size:
//   - engine ms per frame (the queued stroke work done in Editor::update, at the slice JobPacer
//     gives frames that draw in 4 ms), p50 / p95 / max; the picking geometry and index catching up
//     after it; and both together, the frame's work,
//   - pick ms per dab (the picking index, plus mapping the hit to base space), p50 / p95,
//   - pick ms for rays through random pixels (the index alone),
//   - the press that starts a stroke,
//   - undo and redo of the stroke (the call, and the frames of its job when the step is too large
//     for one), with its splits, and of a shorter stroke of about 10k splits,
//   - what the user waits for, frames as the window runs them: mouse-up to the stroke done and
//     shown, Ctrl+Z to the undo done and shown.
// Run on demand: ./brush_bench [levels...]   (default: 4 5, i.e. 940k and 3.8M triangles)
// RGBSUB_BENCH_MESH=FILE.obj replays the path on that file instead, opened with its look (materials,
// texture coordinates, colours: the display's exact channels are then timed too).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "frame_timing.h"
#include "app/editor.h"
#include "app/job_pacer.h"
#include "app/loaded_document.h"
#include "rgb/lod/refine.h"

namespace {

using bench::percentile;

using Clock = std::chrono::steady_clock;
constexpr glm::ivec2 kViewport{1280, 800};
// What JobPacer gives the work when drawing takes 4 ms (a GPU drawing these meshes).
const auto kFrameSlice = std::chrono::microseconds(static_cast<long long>(1000.0 * app::JobPacer::slice_ms(4.0)));

double ms_since(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

// The recorded path: left to right across the middle of the view, waving up and down.
std::vector<glm::vec2> recorded_path() {
    std::vector<glm::vec2> path;
    for (float x = 0.38f * kViewport.x; x <= 0.62f * kViewport.x; x += 5.0f)
        path.push_back({x, 0.55f * kViewport.y + 40.0f * std::sin(x / 40.0f)});
    return path;
}

// An undo or redo as the window runs it: the call, then the frames of its job while there is one
// (a step too large for a frame crosses over several, history_job.h): engine time in all, and the
// longest of the call and those frames.
struct Crossing {
    double ms = 0.0, longest_ms = 0.0;
    std::size_t frames = 0;
};

Crossing cross(app::Editor& editor, bool undo) {
    Crossing c;
    const auto start = Clock::now();
    if (undo) editor.undo();
    else editor.redo();
    c.ms = c.longest_ms = ms_since(start);
    for (; editor.job() != nullptr; ++c.frames) {
        editor.update(kFrameSlice);
        c.ms += editor.timing().frame_ms;
        c.longest_ms = std::max(c.longest_ms, editor.timing().frame_ms);
    }
    return c;
}

struct StrokeResult {
    std::vector<double> engine_ms, geometry_ms, frame_ms, pick_ms;
    double press_ms = 0.0, undo_display_ms = 0.0, redo_display_ms = 0.0;
    Crossing undo, redo;
    // The frames after the undo, each with its slice, until the display has caught up: their count
    // and the longest display work of one.
    std::size_t undo_display_frames = 0;
    double undo_display_frame_max_ms = 0.0;
    // What the user waits for, in wall time with frames as the window runs them: from the mouse-up
    // until the stroke's work is done and the display has caught up (and in how many frames), and
    // from Ctrl+Z until the undo is done and shown.
    double mouse_up_ms = 0.0, undo_shown_ms = 0.0;
    std::size_t mouse_up_frames = 0;
    std::size_t splits = 0;
    std::size_t frames = 0, faces_before = 0, faces_after = 0;
};

// The recorded path, or the part of it given by `fraction`.
StrokeResult replay(app::Editor& editor, app::Modifiers mods, double fraction = 1.0) {
    StrokeResult r;
    r.faces_before = editor.document().mesh().num_faces();
    std::vector<glm::vec2> path = recorded_path();
    path.resize(std::max<std::size_t>(2, static_cast<std::size_t>(fraction * static_cast<double>(path.size()))));
    editor.mouse_moved(path.front());
    editor.mouse_pressed(app::MouseButton::Left, mods);
    r.press_ms = editor.timing().stroke_start_ms;
    std::size_t dabs = editor.timing().dabs;
    auto frame = [&] {
        if (editor.timing().dabs != dabs) r.pick_ms.push_back(editor.timing().last_pick_ms);
        dabs = editor.timing().dabs;
        editor.update(kFrameSlice);
        r.engine_ms.push_back(editor.timing().frame_ms);
        r.geometry_ms.push_back(editor.timing().geometry_ms);
        r.frame_ms.push_back(editor.timing().frame_ms + editor.timing().geometry_ms);
    };
    frame();
    for (const glm::vec2& p : path) {
        editor.mouse_moved(p);
        frame();
    }
    editor.mouse_released(app::MouseButton::Left);
    const auto released = Clock::now();
    const std::size_t frames_before_release = r.engine_ms.size();
    while (editor.job() != nullptr) frame();
    r.mouse_up_frames = r.engine_ms.size() - frames_before_release;
    // Frames that only catch the display up (left out of the engine's figures, as before), each
    // taking the changes as the renderer does.
    for (editor.document().take_display_changes(); !editor.document().display_up_to_date(); ++r.mouse_up_frames) {
        editor.update(kFrameSlice);
        editor.document().take_display_changes();
    }
    r.mouse_up_ms = ms_since(released);
    r.frames = r.engine_ms.size();
    r.faces_after = editor.document().mesh().num_faces();
    const std::size_t vertices = editor.document().mesh().num_vertices();
    // Undo and redo, each followed by what the next frame does for picking (the renderer's buffers
    // follow the same way).
    r.undo = cross(editor, true);
    r.splits = vertices > editor.document().mesh().num_vertices() ? vertices - editor.document().mesh().num_vertices()
                                                                 : editor.document().mesh().num_vertices() - vertices;
    auto start = Clock::now();
    editor.document().geometry();
    r.undo_display_ms = ms_since(start);
    r.redo = cross(editor, false);
    start = Clock::now();
    editor.document().geometry();
    r.redo_display_ms = ms_since(start);
    // The undo again, followed as the window follows it: a frame at a time, Editor::update catching
    // the display up within the slice.
    start = Clock::now();
    editor.undo();
    for (; editor.job() != nullptr || editor.document().display_behind(); ++r.undo_display_frames) {
        editor.update(kFrameSlice);
        r.undo_display_frame_max_ms = std::max(r.undo_display_frame_max_ms, editor.timing().geometry_ms);
    }
    for (editor.document().take_display_changes(); !editor.document().display_up_to_date(); editor.document().take_display_changes())
        editor.update(kFrameSlice);
    r.undo_shown_ms = ms_since(start);
    editor.redo();
    editor.finish_work();
    editor.document().geometry();
    return r;
}

void report(const char* what, const StrokeResult& r) {
    std::printf("  %s: %zu -> %zu triangles over %zu frames, %zu dabs\n", what, r.faces_before, r.faces_after, r.frames, r.pick_ms.size());
    std::printf("    engine per frame p50 %6.2f ms  p95 %6.2f ms  max %6.2f ms | pick per dab p50 %5.3f ms  p95 %5.3f ms\n",
                percentile(r.engine_ms, 0.5), percentile(r.engine_ms, 0.95), percentile(r.engine_ms, 1.0),
                percentile(r.pick_ms, 0.5), percentile(r.pick_ms, 0.95));
    std::printf("    picking geometry and index per frame p50 %5.2f ms  p95 %5.2f ms  max %6.2f ms\n", percentile(r.geometry_ms, 0.5),
                percentile(r.geometry_ms, 0.95), percentile(r.geometry_ms, 1.0));
    std::printf("    both (the frame's work) p50 %6.2f ms  p95 %6.2f ms  max %6.2f ms\n", percentile(r.frame_ms, 0.5),
                percentile(r.frame_ms, 0.95), percentile(r.frame_ms, 1.0));
    std::printf("    stroke start %.3f ms | undo of %zu vertices %.1f ms (+%.1f ms display) | redo %.1f ms (+%.1f ms display)\n",
                r.press_ms, r.splits, r.undo.ms, r.undo_display_ms, r.redo.ms, r.redo_display_ms);
    std::printf("    undo over %zu frames after the call, at most %.1f ms in one | redo over %zu, at most %.1f ms\n", r.undo.frames,
                r.undo.longest_ms, r.redo.frames, r.redo.longest_ms);
    std::printf("    after the undo, frame by frame: the display catches up over %zu frames, at most %.1f ms in one\n",
                r.undo_display_frames, r.undo_display_frame_max_ms);
    std::printf("    waits: mouse-up to the stroke done and shown %.1f ms (%zu frames) | Ctrl+Z to the undo done and shown %.1f ms\n",
                r.mouse_up_ms, r.mouse_up_frames, r.undo_shown_ms);
}

void pick_rays(app::Editor& editor) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> x(0.2f * kViewport.x, 0.8f * kViewport.x), y(0.2f * kViewport.y, 0.8f * kViewport.y);
    std::vector<double> ms;
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        editor.mouse_moved({x(rng), y(rng)});
        const auto start = Clock::now();
        hits += editor.cursor_hit().has_value();
        ms.push_back(ms_since(start));
    }
    std::printf("  pick through random pixels (%d of 1000 hit): p50 %.3f ms  p95 %.3f ms  max %.3f ms\n", hits, percentile(ms, 0.5),
                percentile(ms, 0.95), percentile(ms, 1.0));
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> levels;
    for (int i = 1; i < argc; ++i) levels.push_back(std::atoi(argv[i]));
    if (levels.empty()) levels = {4, 5};
    const char* file = std::getenv("RGBSUB_BENCH_MESH");
    const std::string path = file ? file : std::string(RGBSUB_SOURCE_DIR) + "/assets/bunny.obj";
    for (int level : levels) {
        app::LoadedDocument loaded = app::load_document(path, render::PositionSource::Displayed);
        rgb::refine_uniform(loaded.mesh, level);
        std::printf("%s at level %d: %zu triangles\n", path.c_str(), level, loaded.mesh.num_faces());
        auto start = Clock::now();
        loaded.geometry.rebuild(loaded.mesh);
        loaded.index.rebuild(loaded.mesh, loaded.geometry);
        std::printf("  its display geometry%s and picking index %.0f ms\n", loaded.geometry.appearance() ? " with the file's look" : "",
                    ms_since(start));
        app::Editor editor(kViewport);
        editor.document().adopt(std::move(loaded), path);
        editor.reset_view();
        pick_rays(editor);
        // A brush of about 4000 triangles at this level, one level deeper: about 10k splits a stroke.
        editor.brush().radius_px = 50.0f / std::exp2(static_cast<float>(level - 3));
        editor.brush().falloff = 0.3f;
        editor.brush().target_level = level + 1;
        report("refine one level deeper", replay(editor, {}));
        editor.brush().target_level = level;
        report("coarsen back (Shift)", replay(editor, {.shift = true}));
        // The start of the path: a stroke of about 10k splits, the size the undo goal is stated for.
        editor.brush().target_level = level + 1;
        report("a shorter stroke", replay(editor, {}, 0.17 / std::exp2(static_cast<double>(level - 4))));
    }
    return 0;
}
