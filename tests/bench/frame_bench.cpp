// Frame budget benchmark (issue 33, "Speed at scale"): the editor driven through its input calls on
// the bunny refined uniformly (level 4: 940,544 triangles, level 5: 3,762,176), frames run as the
// window runs them (one Editor::update a frame, at the slice JobPacer gives frames that draw in 4 ms;
// the display's changes taken each frame as the renderer takes them). For each size:
//   - a stroke of dabs along a recorded path (one frame per mouse sample), then frames until its work
//     is done and shown: the wait from the mouse-up,
//   - Ctrl+Z of that stroke, frames until done and shown: the wait from the key,
//   - view-dependent LOD started on that mesh while the camera orbits (a right-drag, one move a frame).
// Per frame, the engine's whole time in Editor::update (the job's step and the display catching up
// with it: the picking geometry and index) p50 / p95 / max, and the catch-up's phases (geometry,
// picking index) summed over the frames, with the slots they handled.
// Run on demand: ./frame_bench [levels...]   (default: 4 5);  ./frame_bench --smoke  (level 1, a few frames)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "frame_timing.h"
#include "app/editor.h"
#include "app/job_pacer.h"
#include "app/loaded_document.h"
#include "rgb/lod/refine.h"

namespace {

using bench::percentile;
using bench::thread_cpu_ms;

using Clock = std::chrono::steady_clock;
constexpr glm::ivec2 kFrameViewport{1280, 800};
// What JobPacer gives the work when drawing takes 4 ms.
const auto kSlice = std::chrono::microseconds(static_cast<long long>(1000.0 * app::JobPacer::slice_ms(4.0)));

double elapsed_ms(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

// The frames of one phase: engine time each (job and catch-up), and the catch-up's parts summed.
struct Frames {
    std::vector<double> engine_ms, cpu_ms;
    struct Worst {
        double total_ms = 0.0, input_ms = 0.0, job_ms = 0.0, catch_up_ms = 0.0;
    } worst;
    double job_ms = 0.0, other_input_ms = 0.0;  // the update's job steps; input less its catching up
    app::CatchUpTiming catch_up;
    std::size_t over_slice = 0;  // frames whose engine time passed the slice by more than a tenth

    // One frame as the window runs it: its input (picking a dab, an undo's first part), then the update.
    template <class Input>
    void run(app::Editor& editor, Input&& input) {
        const auto start = Clock::now();
        const double cpu_start = thread_cpu_ms();
        input();
        const app::CatchUpTiming in_input = editor.document().take_catch_up_timing();
        const double input_ms = elapsed_ms(start);
        editor.update(kSlice);
        editor.document().take_display_changes();
        const app::EngineTiming& t = editor.timing();
        const double ms = input_ms + t.frame_ms + t.geometry_ms;
        engine_ms.push_back(ms);
        cpu_ms.push_back(thread_cpu_ms() - cpu_start);
        if (ms > worst.total_ms) worst = {ms, input_ms, t.frame_ms, t.geometry_ms};
        job_ms += t.frame_ms;
        other_input_ms += input_ms - in_input.geometry_ms - in_input.index_ms;
        catch_up.add(in_input);
        catch_up.add(t.catch_up);
        if (ms > 1.1 * static_cast<double>(kSlice.count()) / 1000.0) ++over_slice;
    }
    // Frames until the work is done and the display shows it.
    void run_until_shown(app::Editor& editor) {
        while (editor.job() != nullptr || !editor.document().display_up_to_date()) run(editor, [] {});
    }
};

void print_frames(const char* what, const Frames& f) {
    std::printf("    %s: %zu frames, engine per frame p50 %6.2f ms  p95 %6.2f ms  max %6.2f ms  (%zu over the slice)\n", what,
                f.engine_ms.size(), percentile(f.engine_ms, 0.5), percentile(f.engine_ms, 0.95), percentile(f.engine_ms, 1.0), f.over_slice);
    double cpu_total = 0.0;
    for (double ms : f.cpu_ms) cpu_total += ms;
    std::printf("      processor time per frame p50 %6.2f ms  p95 %6.2f ms  max %6.2f ms, in all %.0f ms | longest frame: input %.1f, job %.1f, catch-up %.1f ms\n",
                percentile(f.cpu_ms, 0.5), percentile(f.cpu_ms, 0.95), percentile(f.cpu_ms, 1.0), cpu_total, f.worst.input_ms, f.worst.job_ms,
                f.worst.catch_up_ms);
    std::printf("      in all: job %.0f ms, input %.0f ms | catch-up geometry %.0f ms, index %.0f ms, %zu parts, %zu face slots, %zu moved vertices\n",
                f.job_ms, f.other_input_ms, f.catch_up.geometry_ms, f.catch_up.index_ms, f.catch_up.parts, f.catch_up.faces, f.catch_up.vertices);
}

// Left to right across the middle of the view, waving up and down, a sample every 5 px.
std::vector<glm::vec2> stroke_path() {
    std::vector<glm::vec2> path;
    for (float x = 0.38f * kFrameViewport.x; x <= 0.62f * kFrameViewport.x; x += 5.0f)
        path.push_back({x, 0.55f * kFrameViewport.y + 40.0f * std::sin(x / 40.0f)});
    return path;
}

void stroke_and_undo(app::Editor& editor) {
    const std::size_t before = editor.document().mesh().num_faces();
    Frames painting, after_release, undoing;
    const std::vector<glm::vec2> path = stroke_path();
    painting.run(editor, [&] {
        editor.mouse_moved(path.front());
        editor.mouse_pressed(app::MouseButton::Left, {});
    });
    for (const glm::vec2& p : path) painting.run(editor, [&] { editor.mouse_moved(p); });
    const auto released = Clock::now();
    after_release.run(editor, [&] { editor.mouse_released(app::MouseButton::Left); });
    after_release.run_until_shown(editor);
    const double mouse_up_ms = elapsed_ms(released);
    const std::size_t after = editor.document().mesh().num_faces();

    const auto pressed = Clock::now();
    undoing.run(editor, [&] { editor.key_pressed(app::Key::Z, app::Modifiers{.ctrl = true}); });
    undoing.run_until_shown(editor);
    const double undo_ms = elapsed_ms(pressed);

    std::printf("  stroke of %zu mouse samples: %zu -> %zu triangles, undone to %zu\n", path.size(), before, after,
                editor.document().mesh().num_faces());
    print_frames("painting", painting);
    print_frames("after the mouse-up", after_release);
    print_frames("undo", undoing);
    std::printf("    waits: mouse-up to the stroke done and shown %.0f ms | Ctrl+Z to the undo done and shown %.0f ms\n", mouse_up_ms, undo_ms);
}

void orbit_with_view_lod(app::Editor& editor, int frames) {
    editor.detail_settings().view_pixels = 2.0;
    editor.start_view_lod();
    Frames orbiting;
    glm::vec2 at{0.5f * kFrameViewport.x, 0.5f * kFrameViewport.y};
    editor.mouse_moved(at);
    editor.mouse_pressed(app::MouseButton::Right, {});
    const std::size_t before = editor.document().mesh().num_faces();
    for (int i = 0; i < frames; ++i) {
        at.x += 4.0f;
        orbiting.run(editor, [&] { editor.mouse_moved(at); });
    }
    editor.mouse_released(app::MouseButton::Right);
    std::printf("  view-dependent LOD (2 px) while orbiting, %d frames of 4 px: %zu -> %zu triangles\n", frames, before,
                editor.document().mesh().num_faces());
    print_frames("orbit", orbiting);
    editor.freeze_view_lod();
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> levels;
    int orbit_frames = 150;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--smoke") == 0) {
            levels = {1};
            orbit_frames = 10;
        } else {
            levels.push_back(std::atoi(argv[i]));
        }
    }
    if (levels.empty()) levels = {4, 5};
    const std::string path = std::string(RGBSUB_SOURCE_DIR) + "/assets/bunny.obj";
    std::printf("slice %.1f ms a frame (JobPacer, drawing 4 ms)\n", static_cast<double>(kSlice.count()) / 1000.0);
    for (int level : levels) {
        app::LoadedDocument loaded = app::load_document(path, render::PositionSource::Displayed);
        rgb::refine_uniform(loaded.mesh, level);
        loaded.geometry.rebuild(loaded.mesh);
        loaded.index.rebuild(loaded.mesh, loaded.geometry);
        std::printf("bunny at level %d: %zu triangles\n", level, loaded.mesh.num_faces());
        app::Editor editor(kFrameViewport);
        editor.document().adopt(std::move(loaded), path);
        editor.reset_view();
        // A brush of about 4000 triangles at this level, one level deeper (as brush_bench).
        editor.brush().radius_px = 50.0f / std::exp2(static_cast<float>(level - 3));
        editor.brush().falloff = 0.3f;
        editor.brush().target_level = level + 1;
        stroke_and_undo(editor);
        orbit_with_view_lod(editor, orbit_frames);
    }
    return 0;
}
