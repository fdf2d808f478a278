// rgbsub edit --screenshot: a full editor frame through OSMesa, panels included. Checked by what
// each part of the frame must look like: the framed mesh in the middle of what the panel leaves
// free, the dark panel at the top right and status bar at the bottom, the brush ring around the
// resting mouse, white elsewhere.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "app/crease_tool.h"
#include "app/editor.h"
#include "app/headless_frame.h"
#include "gl_test_support.h"
#include "io/mesh_file.h"
#include "render/colour_map.h"
#include "render/image.h"
#include "rgb/lod/requests.h"
#include "small_meshes.h"
#include "test_meshes.h"
#include "test_paths.h"
#include "textured_quad.h"
#include "support/set_level.h"

namespace app {
namespace {

// The plain surface colour under light: grey, neither the white background nor the dark panel.
bool is_mesh_grey(glm::u8vec4 p) {
    const int lo = std::min({p.r, p.g, p.b}), hi = std::max({p.r, p.g, p.b});
    return hi - lo < 16 && lo > 60 && hi < 235;
}
bool is_dark(glm::u8vec4 p) { return std::max({p.r, p.g, p.b}) < 80; }
bool is_white(glm::u8vec4 p) { return p.r == 255 && p.g == 255 && p.b == 255; }
// The brush ring's orange (1, 0.55, 0) blended over the grey surface.
bool is_orange(glm::u8vec4 p) { return p.r > 150 && p.r > p.g + 40 && p.g > p.b + 40; }

class HeadlessFrameImage : public ::testing::Test {
protected:
    void SetUp() override {
        frame.size = {800, 600};
        image = render_editor_frame(std::string(RGBSUB_SOURCE_DIR) + "/assets/default.obj", frame);
        ASSERT_EQ(image.width, 800);
        ASSERT_EQ(image.height, 600);
    }
    // Fraction of the pixels in [x0, x1) x [y0, y1) that pass `test`.
    template <class Test>
    double fraction(int x0, int y0, int x1, int y1, Test test) const {
        std::size_t n = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) n += test(image.pixel(x, y));
        return static_cast<double>(n) / static_cast<double>((x1 - x0) * (y1 - y0));
    }
    HeadlessFrame frame;
    render::Image image;
};

// The panel is kPanelWidth (320) pixels wide at the top right, kPanelCover with its margin, and the
// view is framed on what it leaves free, so the mesh's silhouette is centred there; a one-line
// status bar runs along the bottom.
TEST_F(HeadlessFrameImage, DrawsTheMeshCentredInTheFreePartThePanelAndTheStatusBar) {
    const int free_width = 800 - static_cast<int>(kPanelCover), free_centre = free_width / 2;
    EXPECT_GT(fraction(free_width + 10, 40, 800 - 20, 300, is_dark), 0.6) << "the panel's dark background";
    EXPECT_EQ(fraction(0, 0, 60, 60, is_white), 1.0) << "the top-left corner shows the background";
    EXPECT_EQ(fraction(0, 480, 60, 540, is_white), 1.0) << "and so does the bottom-left one above the status bar";
    EXPECT_GT(fraction(0, 590, 800, 600, is_dark), 0.6) << "the status bar";

    int x_min = image.width, x_max = -1, y_min = image.height, y_max = -1;
    std::size_t grey = 0;
    for (int y = 0; y < 560; ++y)  // above the status bar, whose text is grey too
        for (int x = 0; x < free_width; ++x)
            if (is_mesh_grey(image.pixel(x, y))) {
                ++grey;
                x_min = std::min(x_min, x), x_max = std::max(x_max, x), y_min = std::min(y_min, y), y_max = std::max(y_max, y);
            }
    EXPECT_GT(grey, 800u * 600u / 10) << "the framed mesh covers a good part of the view";
    EXPECT_FALSE(is_white(image.pixel(free_centre, 300))) << "the mesh covers the centre of the free part";
    EXPECT_NEAR(0.5 * (x_min + x_max), free_centre, 0.1 * free_width);
    EXPECT_NEAR(0.5 * (y_min + y_max), 300.0, 0.1 * 600);
    EXPECT_LT(x_min, free_centre - 100) << "the silhouette reaches well left of the free part's centre";
    EXPECT_GT(x_max, free_centre + 100) << "and well right of it";
    EXPECT_GT(x_max - x_min, free_width / 2) << "and spans over half the free part's width, the side it is framed in";
}

// The cursor rests in the middle of the free part: the brush's 40-pixel ring surrounds it, hollow,
// and there is no orange anywhere else.
TEST_F(HeadlessFrameImage, DrawsTheBrushRingAroundTheRestingMouse) {
    const glm::vec2 cursor = frame.cursor * glm::vec2(frame.size);
    std::size_t orange = 0;
    double nearest = 1e9, furthest = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (is_orange(image.pixel(x, y))) {
                ++orange;
                const double d = glm::distance(glm::vec2(x, y), cursor);
                nearest = std::min(nearest, d);
                furthest = std::max(furthest, d);
            }
    EXPECT_GT(orange, 100u) << "a ring of about 2 pi 40 pixels";
    EXPECT_GT(nearest, 20.0) << "hollow";
    EXPECT_LT(furthest, 60.0);
}

// `rgbsub edit --screenshot --mode texture` on textured_quad.h's square: the mesh's pixels (in the
// free part, away from the brush ring) by colour class, and the mean column of each class.
struct TexturedFrame {
    std::size_t red = 0, blue = 0, neutral = 0, green = 0;
    double red_x = 0.0, blue_x = 0.0;

    explicit TexturedFrame(const std::string& texture) {
        const std::filesystem::path folder = std::filesystem::path(::testing::TempDir()) / "frame_texture";
        HeadlessFrame frame;
        frame.size = {800, 600};
        frame.colouring = render::Colouring::Texture;
        const render::Image image = render_editor_frame(test::write_textured_quad(folder, texture).string(), frame);
        const glm::vec2 cursor = frame.cursor * glm::vec2(frame.size);
        const int free_width = 800 - static_cast<int>(kPanelCover);
        for (int y = 0; y < 560; ++y)  // above the status bar
            for (int x = 0; x < free_width; ++x) {
                if (glm::distance(glm::vec2(x, y), cursor) < 60.0f) continue;
                switch (render_test::classify(image, x, y)) {
                    case render_test::PixelClass::Red: ++red, red_x += x; break;
                    case render_test::PixelClass::Blue: ++blue, blue_x += x; break;
                    case render_test::PixelClass::Neutral: ++neutral; break;
                    case render_test::PixelClass::Green: ++green; break;
                    case render_test::PixelClass::Background: break;
                }
            }
        red_x /= std::max<std::size_t>(red, 1);
        blue_x /= std::max<std::size_t>(blue, 1);
    }
};

// The default view looks at the square's front from the front right (+x to the right on screen):
// the texture's red half (u < 0.5, x < 0.5) shows left of its blue half, each about half the square
// (perspective makes the nearer one larger); the material's green is not used.
TEST(HeadlessFrame, TextureModeShowsTheDiffuseTextureOverTheUvs) {
    const TexturedFrame frame("halves.png");
    EXPECT_GT(frame.red, 20000u);
    EXPECT_GT(frame.blue, 20000u);
    EXPECT_LT(frame.red_x, frame.blue_x);
    EXPECT_NEAR(static_cast<double>(frame.red) / static_cast<double>(frame.blue), 1.0, 0.4);
    EXPECT_LT(frame.neutral + frame.green, (frame.red + frame.blue) / 20) << "only filtering at the edges blends the colours";
}

// A map_Kd that is not there: the square shows the texture checker, light grey and dark blue cells
// of equal number (8 x 8 over the square), nothing red.
TEST(HeadlessFrame, TextureModeShowsTheCheckerForAMissingTexture) {
    const TexturedFrame frame("gone.png");
    EXPECT_EQ(frame.red, 0u);
    EXPECT_EQ(frame.green, 0u);
    EXPECT_GT(frame.blue, 20000u);
    EXPECT_NEAR(static_cast<double>(frame.neutral) / static_cast<double>(frame.blue), 1.0, 0.3);
}

TEST(HeadlessFrame, ALoadErrorIsReported) {
    EXPECT_THROW(render_editor_frame("/nonexistent/mesh.obj", HeadlessFrame{}), std::runtime_error);
}

// Opening a dense mesh: the question, the cage being made, and the cage with its detail. The frames
// are written to the test's temporary folder (dense_*.png) for a person to look at.
TEST(HeadlessFrame, ADenseMeshShowsTheCageQuestionThenTheCageWithItsDetail) {
    const std::filesystem::path folder = test::fresh_folder("dense_frames");
    const std::string file = test::write_torus(folder, 120, 60);  // 14,400 triangles
    HeadlessFrame frame;
    frame.size = {1280, 800};
    EditorOptions options;
    options.viewport = frame.size;
    options.dense_mesh_triangles = 10000;
    Editor editor(options);
    editor.request_open(file);
    while (editor.file_task() != nullptr) {
        editor.update(std::chrono::milliseconds(5));
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ASSERT_EQ(editor.pending(), Pending::DenseMesh);
    const auto write = [&](const render::Image& image, const char* name) {
        std::ofstream(folder / name, std::ios::binary) << render::encode_png(image);
    };
    const auto dark_share = [](const render::Image& image, int x0, int y0, int x1, int y1) {
        std::size_t n = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) n += is_dark(image.pixel(x, y));
        return static_cast<double>(n) / static_cast<double>((x1 - x0) * (y1 - y0));
    };
    const render::Image question = render_editor_frame(editor, frame);
    write(question, "dense_question.png");
    // The modal's dark box in the middle of the window (nothing is open behind it).
    EXPECT_GT(dark_share(question, 540, 380, 740, 420), 0.5);

    editor.answer_dense_mesh(true);
    write(render_editor_frame(editor, frame), "dense_making.png");
    editor.finish_work();
    ASSERT_NE(editor.document().mesh().base().detail(), nullptr) << editor.message();
    frame.colouring = render::Colouring::Level;
    frame.wireframe = true;
    const render::Image cage = render_editor_frame(editor, frame);
    write(cage, "dense_cage.png");
    EXPECT_LT(dark_share(cage, 400, 380, 500, 420), 0.5) << "no dialog is left";
}

// The distance heat map: on a cage with detail the mesh in the bands' colours and the legend with every
// band's swatch (written to the test's temporary folder as distance_frame.png for a person to look
// at); on a mesh without detail the mode is not offered, and the frame shows the plain shading.
TEST(HeadlessFrame, DistanceHeatMapOnACageWithDetailOnly) {
    const std::filesystem::path folder = test::fresh_folder("distance_frames");
    rgb::Mesh cage = render_test::bumpy_cage(1, 4);
    rgbtest::set_level(cage, 3, rgb::Sphere{{0.0, 0.0, 1.0}, 0.7});
    rgbio::save_mesh(cage, (folder / "cage.obj").string());
    HeadlessFrame frame;
    frame.size = {1280, 800};
    frame.colouring = render::Colouring::DetailDistance;
    // Pixels in each band's colour unlit, as its swatch shows it (up to the rounding to bytes).
    const auto swatch_pixels = [](const render::Image& image) {
        std::array<std::size_t, render::kDistanceBands> counts{};
        for (int band = 0; band < render::kDistanceBands; ++band) {
            const glm::ivec3 swatch(glm::round(255.0f * render::distance_colour(band)));
            for (int y = 0; y < image.height; ++y)
                for (int x = 0; x < image.width; ++x) {
                    const glm::ivec3 d = glm::abs(glm::ivec3(glm::u8vec3(image.pixel(x, y))) - swatch);
                    counts[static_cast<std::size_t>(band)] += std::max({d.r, d.g, d.b}) <= 1;
                }
        }
        return counts;
    };
    const render::Image heat = render_editor_frame((folder / "cage.obj").string(), frame);
    std::ofstream(folder / "distance_frame.png", std::ios::binary) << render::encode_png(heat);
    for (std::size_t count : swatch_pixels(heat)) EXPECT_GE(count, 16u * 16u);
    for (std::size_t count : swatch_pixels(render_editor_frame(std::string(RGBSUB_SOURCE_DIR) + "/assets/default.obj", frame)))
        EXPECT_EQ(count, 0u);
}

// Sharp edges (issue 33): the crease tool's tags are drawn in the magenta of `rgbsub render` in every
// display mode, as sharp_edges_screenshot_test.cpp checks render's (sharp_<mode>.png in the test's
// temporary folder for a person to look at). The machined part at level 2, its 44 edges above 30
// degrees tagged, against the same part untagged.
TEST(HeadlessFrame, SharpEdgesAreMagentaLinesInEveryDisplayMode) {
    const std::filesystem::path folder = test::fresh_folder("sharp_frames");
    HeadlessFrame frame;
    frame.size = {800, 600};
    Editor tagged(frame.size), untagged(frame.size);
    for (Editor* editor : {&tagged, &untagged}) {
        editor->set_covered_right(kPanelCover);
        editor->load(test::asset_path("machined_part.obj"));
        editor->start_flood_fill(2);
        editor->finish_work();
    }
    ASSERT_TRUE(tagged.set_sharp_features(with_edges_above(tagged.document().mesh(), 30.0), "tag edges above 30 degrees"));
    // render's test's magenta, in the part of the frame the panel and the status bar leave free.
    const auto magenta = [&](const render::Image& image) {
        std::size_t n = 0;
        for (int y = 0; y < frame.size.y - 40; ++y)
            for (int x = 0; x < frame.size.x - static_cast<int>(kPanelCover); ++x) {
                const glm::u8vec4 p = image.pixel(x, y);
                n += p.r > 150 && p.b > 80 && p.g + 60 < p.b;
            }
        return n;
    };
    struct Mode {
        const char* name;
        render::Shading shading;
        render::Colouring colouring;
        bool wireframe;
    };
    const Mode modes[] = {{"shaded", render::Shading::Smooth, render::Colouring::Plain, false},
                          {"wire", render::Shading::Smooth, render::Colouring::Plain, true},
                          {"rgb", render::Shading::Flat, render::Colouring::RgbType, false},
                          {"level", render::Shading::Smooth, render::Colouring::Level, false},
                          {"material", render::Shading::Smooth, render::Colouring::Material, false},
                          {"checker", render::Shading::Smooth, render::Colouring::Checker, false}};
    for (const Mode& mode : modes) {
        frame.shading = mode.shading;
        frame.colouring = mode.colouring;
        frame.wireframe = mode.wireframe;
        const render::Image shown = render_editor_frame(tagged, frame);
        std::ofstream(folder / (std::string("sharp_") + mode.name + ".png"), std::ios::binary) << render::encode_png(shown);
        EXPECT_GT(magenta(shown), magenta(render_editor_frame(untagged, frame)) + 300) << mode.name << ": 44 crease edges, several pixels each";
    }
}

// The Detail panel's amount is a float field: drawn, it leaves the default 0.1% as typed, so the
// job, the status line and the script line say "0.1%", not the float's "0.10000000149011612%".
TEST(HeadlessFrame, ThePanelKeepsAmountsAsPeopleWriteThem) {
    EditorOptions options;
    options.viewport = {1280, 800};
    options.covered_right = kPanelCover;
    Editor editor(options);
    ASSERT_TRUE(editor.open(test::asset_path("default.obj")));
    HeadlessFrame frame;
    render_editor_frame(editor, frame);
    editor.start_detail_edit();
    ASSERT_NE(editor.job(), nullptr);
    EXPECT_EQ(editor.job()->label(), "tolerance 0.1%");
    editor.finish_work();
    EXPECT_NE(editor.message().find("tolerance 0.1%"), std::string::npos) << editor.message();
}

// The axis gizmo in the bottom left corner: the mesh frame's X, Y and Z in red, green and blue; in
// the top view Y points at the viewer, so its disc covers the centre. Written as gizmo_*.png.
TEST(HeadlessFrame, TheAxisGizmoShowsTheMeshFramesAxes) {
    const std::filesystem::path folder = test::fresh_folder("gizmo_frames");
    EditorOptions options;
    options.viewport = {1280, 800};
    Editor editor(options);
    ASSERT_TRUE(editor.open(test::asset_path("default.obj")));
    HeadlessFrame frame;
    frame.axis_gizmo = true;
    const auto corner_has = [&](const render::Image& image, auto colour) {
        int n = 0;
        for (int y = 800 - 26 - 110; y < 800 - 26; ++y)
            for (int x = 0; x < 110; ++x) n += colour(image.pixel(x, y));
        return n;
    };
    const auto red = [](glm::u8vec4 p) { return p.r > 180 && p.g < 100 && p.b < 100; };
    const auto green = [](glm::u8vec4 p) { return p.g > 160 && p.r < 120 && p.b < 120; };
    const auto blue = [](glm::u8vec4 p) { return p.b > 190 && p.r < 120 && p.g < 160; };
    const render::Image perspective = render_editor_frame(editor, frame);
    std::ofstream(folder / "gizmo_perspective.png", std::ios::binary) << render::encode_png(perspective);
    EXPECT_GT(corner_has(perspective, red), 30);
    EXPECT_GT(corner_has(perspective, green), 30);
    EXPECT_GT(corner_has(perspective, blue), 30);

    editor.key_pressed(Key::Keypad7, {});
    editor.key_pressed(Key::Keypad5, {});
    const render::Image top = render_editor_frame(editor, frame);
    std::ofstream(folder / "gizmo_top_orthographic.png", std::ios::binary) << render::encode_png(top);
    const glm::u8vec4 middle = top.pixel(52, 800 - 26 - 52);
    EXPECT_TRUE(green(middle)) << "Y towards the viewer: " << int(middle.r) << " " << int(middle.g) << " " << int(middle.b);
}

// Export LODs: the slider shows a level in place of the mesh, and its left end the mesh again as it
// was. The frames, the section open with its table, are written to the test's temporary folder
// (lods_*.png) for a person to look at.
TEST(HeadlessFrame, ExportLodsPreviewsALevelInPlaceOfTheMesh) {
    const std::filesystem::path folder = test::fresh_folder("lods_frames");
    EditorOptions options;
    options.viewport = {960, 600};
    Editor editor(options);
    ASSERT_TRUE(editor.open(test::asset_path("default.obj")));
    HeadlessFrame frame;
    frame.size = options.viewport;
    frame.colouring = render::Colouring::Level;
    frame.wireframe = true;
    for (const char* folded : {"Brush", "Whole mesh", "Detail by size, accuracy, view", "Display"}) frame.layout.sections[folded] = false;
    frame.layout.sections["Export LODs"] = true;
    const render::Image mesh = render_editor_frame(editor, frame);
    editor.lod_export_settings().values = "3,1";
    editor.start_lod_levels();
    editor.finish_work();
    ASSERT_NE(editor.lod_levels(), nullptr) << editor.lod_problem();
    editor.preview_lod(0);
    const render::Image level = render_editor_frame(editor, frame);
    std::ofstream(folder / "lods_preview.png", std::ios::binary) << render::encode_png(level);
    editor.preview_lod(std::nullopt);
    const render::Image again = render_editor_frame(editor, frame);
    std::ofstream(folder / "lods_mesh.png", std::ios::binary) << render::encode_png(again);
    // The viewport, left of the panel and above the status bar.
    const auto differing = [](const render::Image& a, const render::Image& b) {
        std::size_t n = 0;
        for (int y = 0; y < 560; ++y)
            for (int x = 0; x < 600; ++x) n += a.pixel(x, y) != b.pixel(x, y);
        return n;
    };
    EXPECT_GT(differing(mesh, level), 10000u) << "level 3's 12,288 triangles in its heat colour in place of the 192 of level 0";
    EXPECT_EQ(differing(mesh, again), 0u);
}

}  // namespace
}  // namespace app
