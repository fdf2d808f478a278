#pragma once
// A full editor frame, panels included, rendered headless through OSMesa: the README's screenshots
// come from the program itself. Needs no display.
#include <string>

#include <glm/vec2.hpp>

#include "app/editor_settings.h"
#include "render/image.h"
#include "render/renderer.h"

namespace app {

struct HeadlessFrame {
    glm::ivec2 size{1280, 800};
    render::Shading shading = render::Shading::Smooth;
    render::Colouring colouring = render::Colouring::Plain;
    bool wireframe = false;
    // Where the mouse rests, as a fraction of the size (the brush cursor shows there): the middle of
    // what the panel leaves free.
    glm::vec2 cursor{0.37f, 0.5f};
    // The window's axis gizmo: off, so that a frame shows the mesh and the panels alone (the
    // screenshots, and tests that judge a frame by its colours).
    bool axis_gizmo = false;
    // The panel's sections open or folded (none named: as in a new window).
    PanelLayout layout;
};

// Opens `file` in an editor and renders one frame of it. Throws rgbio::ObjError when the file cannot
// be loaded, std::runtime_error when no OSMesa context can be made.
render::Image render_editor_frame(const std::string& file, const HeadlessFrame& frame);

class Editor;
// One frame of `editor` as it stands, dialogs included (a question it asks, a cage being made):
// the editor's viewport should be frame.size.
render::Image render_editor_frame(Editor& editor, const HeadlessFrame& frame);

}  // namespace app
