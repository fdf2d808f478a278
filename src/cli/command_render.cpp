// `rgbsub render`: a headless screenshot of an OBJ through OSMesa, framed automatically.
#include <charconv>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/mesh_io_support.h"
#include "io/files/atomic_file.h"
#include "io/mesh_file.h"
#include "io/scale_check.h"
#include "io/script/triangle_limit.h"
#include "render/headless.h"
#include "rgb/lod/lod_criteria.h"
#include "rgb/lod/screen_detail.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/loop_geometry.h"

namespace cli {
namespace {

constexpr std::string_view kUsage =
    "usage: rgbsub render IN.obj -o OUT.png [--size WxH] [--mode shaded|flat|rgb|level|distance] [--wire]\n"
    "                     [--view AZIMUTH,ELEVATION] [--limit] [--base] [--screen-lod PX [--lod-view AZ,EL]]\n"
    "                     [--max-triangles N] [--strict] [--sharp-angle DEG] [--boundary edge-only|edge-and-corner]\n"
    "Renders the mesh headless (OSMesa, no display needed), framed automatically.\n"
    "  -o, --output PATH   the PNG to write (saved like OBJ files: see docs/files.md)\n"
    "  --size WxH          image size in pixels (default 1024x768)\n"
    "  --mode MODE         shaded (smooth), flat, rgb (triangle types: green/red/blue),\n"
    "                      level (heat map of face levels with a legend), distance (on a cage\n"
    "                      with detail, made by rgbsub remesh: each triangle's largest distance\n"
    "                      to the dense mesh, in fixed bands from 0.001% to 1% of the mesh's size,\n"
    "                      with a legend in % and in units; see docs/detail.md); default shaded\n"
    "  --wire              draw the triangle edges\n"
    "  --view AZ,EL        camera azimuth and elevation in degrees (default 30,20)\n"
    "  --limit             limit-surface positions where the mesh holds a vertex's ring,\n"
    "                      displayed positions elsewhere (the count is reported)\n"
    "  --base              overlay the base mesh's edges\n"
    "  --screen-lod PX     first set the detail for this view: edges longer than PX pixels on\n"
    "                      screen are split, none is finer than that, and detail outside the view\n"
    "                      or on faces turned away goes (the editor's view-dependent mode, settled)\n"
    "  --lod-view AZ,EL    set that detail for another view of the same framing (to see it from aside)\n"
    "  --strict            refuse a non-manifold input instead of cutting it apart\n"
    "  --sharp-angle DEG, --boundary B   crease tags added to the file's (see rgbsub refine --help);\n"
    "                      sharp edges are drawn as coloured lines\n"
    "The same input gives the same bytes.\n";

constexpr int kMaxImageSide = 8192;

template <class T>
T parse_part(std::string_view text, std::string_view option, std::string_view whole) {
    T value{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size())
        throw UsageError(std::string(option) + ": cannot read '" + std::string(whole) + "'");
    return value;
}

glm::ivec2 parse_size(const std::string& text) {
    const std::size_t x = text.find('x');
    if (x == std::string::npos) throw UsageError("--size expects WIDTHxHEIGHT, got '" + text + "'");
    const glm::ivec2 size(parse_part<int>(std::string_view(text).substr(0, x), "--size", text),
                          parse_part<int>(std::string_view(text).substr(x + 1), "--size", text));
    if (size.x < 1 || size.y < 1 || size.x > kMaxImageSide || size.y > kMaxImageSide)
        throw UsageError("--size must be between 1x1 and " + std::to_string(kMaxImageSide) + "x" +
                         std::to_string(kMaxImageSide) + ", got " + text);
    return size;
}

void parse_view(const std::string& text, render::HeadlessView& view) {
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos) throw UsageError("--view expects AZIMUTH,ELEVATION in degrees, got '" + text + "'");
    view.azimuth_deg = parse_part<float>(std::string_view(text).substr(0, comma), "--view", text);
    view.elevation_deg = parse_part<float>(std::string_view(text).substr(comma + 1), "--view", text);
    if (!std::isfinite(view.azimuth_deg) || !std::isfinite(view.elevation_deg))
        throw UsageError("--view: angles must be finite numbers, got '" + text + "'");
    if (view.elevation_deg < -90.0f || view.elevation_deg > 90.0f)
        throw UsageError("--view: elevation must be between -90 and 90, got '" + text + "'");
}

void apply_mode(const std::string& mode, render::RenderOptions& options) {
    if (mode == "shaded") {
        options.shading = render::Shading::Smooth;
    } else if (mode == "flat") {
        options.shading = render::Shading::Flat;
    } else if (mode == "rgb") {
        options.shading = render::Shading::Flat;
        options.colouring = render::Colouring::RgbType;
    } else if (mode == "level") {
        options.colouring = render::Colouring::Level;
    } else if (mode == "distance") {
        options.colouring = render::Colouring::DetailDistance;
    } else {
        throw UsageError("--mode must be shaded, flat, rgb, level or distance, got '" + mode + "'");
    }
}

}  // namespace

int run_render(std::span<const std::string> args) {
    const Arguments arguments(args, {"--wire", "--limit", "--base", kStrictSwitch},
                              {"--output", "--size", "--mode", "--view", "--screen-lod", "--lod-view", "--max-triangles", kSharpAngleOption,
                               kBoundaryOption},
                              {{"-o", "--output"}});
    if (arguments.has("--help")) {
        std::cout << kUsage;
        return exit_ok;
    }
    if (arguments.positional().size() != 1) throw UsageError("expects exactly one IN.obj");
    const std::optional<std::string> output = arguments.value("--output");
    if (!output) throw UsageError("needs -o OUT.png");

    render::HeadlessView view;
    view.size = {1024, 768};
    if (const auto size = arguments.value("--size")) view.size = parse_size(*size);
    if (const auto angles = arguments.value("--view")) parse_view(*angles, view);
    render::RenderOptions options;
    apply_mode(arguments.value("--mode").value_or("shaded"), options);
    options.wireframe = arguments.has("--wire");
    options.base_mesh_overlay = arguments.has("--base");
    if (arguments.has("--limit")) options.positions = render::PositionSource::Limit;

    std::optional<double> screen_pixels;
    if (arguments.has("--screen-lod")) {
        screen_pixels = arguments.number("--screen-lod", 0.0);
        if (!(*screen_pixels >= 0.5) || !std::isfinite(*screen_pixels))
            throw UsageError("--screen-lod expects an edge length in pixels, at least 0.5");
    }
    render::HeadlessView lod_view = view;
    if (const auto angles = arguments.value("--lod-view")) {
        if (!screen_pixels) throw UsageError("--lod-view needs --screen-lod");
        parse_view(*angles, lod_view);
    }
    const auto limit = static_cast<std::size_t>(
        arguments.integer("--max-triangles", static_cast<long>(rgbio::default_triangle_limit(rgbio::MemoryUse::ScreenLod)), 1, 4'000'000'000l));

    const std::string& input = arguments.positional().front();
    std::vector<std::string> warnings;
    check_output_first(*output);
    rgb::Mesh mesh = with_sharp_options(arguments, rgbio::load_mesh(input, &warnings, read_options(arguments)));
    for (const std::string& warning : warnings) std::cerr << "rgbsub render: " << input << ": " << warning << '\n';
    if (const std::optional<std::string> problem = rgbio::scale_problem(mesh.base().positions(), rgbio::kFloatScale))
        throw std::invalid_argument(input + ": cannot render it (the renderer works in 32-bit floats): " + *problem);
    if (options.colouring == render::Colouring::DetailDistance && !mesh.base().detail())
        throw std::invalid_argument(input + ": --mode distance needs a cage with detail (made by rgbsub remesh), and this mesh has none");
    render::Image image;
    try {
        image = render::render_headless(mesh, options, view, nullptr, [&](const render::OrbitCamera& camera) {
            if (!screen_pixels) return;
            rgb::DetailRequest request;
            render::OrbitCamera lod_camera = camera;
            lod_camera.azimuth_deg = lod_view.azimuth_deg;
            lod_camera.elevation_deg = lod_view.elevation_deg;
            request.value = rgb::ScreenCriterion(mesh.shared_base(), render::screen_view(lod_camera, view.size)).edge_value();
            request.threshold = *screen_pixels;
            request.max_triangles = limit;
            rgbio::check_detail_size(mesh, request, limit);
            if (rgb::apply_detail_request(mesh, request).budget_bound)
                throw rgbio::TooLarge("the view's detail needs more than " + std::to_string(limit) + " triangles (--max-triangles)");
            std::cout << "rgbsub render: detail for the view: " << mesh.num_faces() << " triangles\n";
        });
    } catch (const rgbio::TooLarge&) {
        throw;
    } catch (const std::runtime_error& error) {
        throw std::runtime_error(std::string("cannot render headless: ") + error.what());
    }
    rgbio::write_file_atomically(*output, render::encode_png(image));
    return exit_ok;
}

}  // namespace cli
