// Texture coordinates through save and load (issue 12): a refined or adaptive mesh is written with
// each corner's exact UV (vt and f v/vt lines) and the base UV channel in the state's base-uvs
// section, so load -> refine -> save -> load -> level 0 gives back the input's UVs bit for bit, and
// a resumed mesh shows the same UVs as the saved one.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/base_uvs.h"
#include "io/mesh_file.h"
#include "io/obj/number_format.h"
#include "io/obj_reader.h"
#include "obj_test_support.h"
#include "rgb/lod/refine.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/face_location.h"
#include "rgb/values/mesh_uvs.h"
#include "rgb/values/uv_evaluator.h"
#include "textured_grid.h"
#include "support/set_level.h"

namespace rgbio {
namespace {

using test::textured_grid;

struct MeshWithUvs {
    LoadedMesh loaded;
    rgb::Mesh mesh;
    std::shared_ptr<const rgb::UvLayout> uvs;
};

MeshWithUvs load(const std::string& text, std::optional<rgb::UvInterpolation> option = std::nullopt) {
    LoadedMesh loaded = read_obj_text(text, "test.obj");
    rgb::Mesh mesh = build_mesh(loaded);
    std::vector<std::string> warnings;
    auto uvs = uv_layout(base_uv_channel(loaded, mesh, warnings), mesh, option);
    EXPECT_TRUE(warnings.empty());
    return {std::move(loaded), std::move(mesh), std::move(uvs)};
}

// Every corner of `m` (at level 0) shows the UV the input gave that corner, bit for bit.
testing::AssertionResult shows_the_input_uvs(const MeshWithUvs& m, const LoadedMesh& input) {
    rgb::UvEvaluator uvs(m.mesh.base(), *m.uvs);
    for (rgb::FaceId f : m.mesh.faces()) {
        const std::uint32_t g = rgb::base_face_of(m.mesh, f);
        const rgb::Triangle& t = input.triangles[g];
        if (input.triangle_texcoords[g][0] == kNoIndex) continue;  // a face the input gave no UVs
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t v = m.mesh.face_vertices(f)[static_cast<std::size_t>(c)].idx;
            const auto k = static_cast<std::size_t>(std::find(t.begin(), t.end(), v) - t.begin());
            if (rgb::displayed_uv(m.mesh, uvs, f, c) != input.texcoords[input.triangle_texcoords[g][k]])
                return testing::AssertionFailure() << "corner " << c << " of face " << f.idx << " (base face " << g << ")";
        }
    }
    return testing::AssertionSuccess();
}

std::string saved(const MeshWithUvs& m) {
    SaveOptions options;
    options.uvs = m.uvs;
    return format_obj(m.mesh, options);
}

TEST(UvRoundTrip, RefinedSaveResumesAndLevelZeroGivesBackTheInputUvsBitForBit) {
    const std::string input = textured_grid();
    MeshWithUvs original = load(input);
    ASSERT_NE(original.uvs, nullptr);
    rgbtest::set_level(original.mesh, 3, rgb::Sphere{{2, 1.5, 0}, 1.2});
    rgb::LevelRequest everywhere;
    everywhere.kind = rgb::RequestKind::Refine;
    everywhere.level = 1;
    rgb::apply_request(original.mesh, everywhere);

    MeshWithUvs resumed = load(saved(original));
    ASSERT_TRUE(resumed.loaded.adaptive);
    ASSERT_NE(resumed.uvs, nullptr);
    EXPECT_EQ(resumed.uvs->channel(), original.uvs->channel());
    // The file's corners hold the saved mesh's UVs, bit for bit (f lines are live faces in slot order).
    rgb::UvEvaluator evaluator(original.mesh.base(), *original.uvs);
    std::size_t line = 0;
    for (rgb::FaceId f : original.mesh.faces()) {
        for (int c = 0; c < 3; ++c)
            ASSERT_EQ(resumed.loaded.texcoords[resumed.loaded.triangle_texcoords[line][static_cast<std::size_t>(c)]],
                      rgb::displayed_uv(original.mesh, evaluator, f, c));
        ++line;
    }

    rgbtest::set_level(resumed.mesh, 0);
    EXPECT_TRUE(shows_the_input_uvs(resumed, read_obj_text(input, "test.obj")));
}

// Issue 12's textured models from Debian's assimp-testmodels (regr01 has faces without vt).
TEST(UvRoundTrip, TheAssimpTexturedModelsComeBackFromRefinementWithTheirUvs) {
    const std::filesystem::path corpus = "/usr/share/assimp/models/OBJ";
    ASSERT_TRUE(std::filesystem::is_directory(corpus)) << corpus << " is missing: install the Debian package assimp-testmodels";
    for (const char* name : {"spider.obj", "WusonOBJ.obj", "regr01.obj"}) {
        const LoadedMesh input = read_obj_file((corpus / name).string());
        rgb::Mesh mesh = build_mesh(input);
        std::vector<std::string> warnings;
        MeshWithUvs m{input, std::move(mesh), nullptr};
        m.uvs = uv_layout(base_uv_channel(input, m.mesh, warnings), m.mesh, std::nullopt);
        ASSERT_NE(m.uvs, nullptr) << name;
        rgbtest::set_level(m.mesh, 2);
        MeshWithUvs resumed = load(saved(m));
        rgbtest::set_level(resumed.mesh, 0);
        EXPECT_TRUE(shows_the_input_uvs(resumed, input)) << name;
    }
}

TEST(UvRoundTrip, LimitPositionsComeWithLimitUvs) {
    MeshWithUvs m = load(textured_grid());
    rgbtest::set_level(m.mesh, 2, rgb::Sphere{{2, 1, 0}, 1.0});
    SaveOptions options;
    options.uvs = m.uvs;
    options.positions = SavedPositions::Limit;
    const LoadedMesh file = read_obj_text(format_obj(m.mesh, options), "test.obj");
    rgb::UvEvaluator evaluator(m.mesh.base(), *m.uvs);
    std::size_t line = 0, differing = 0;
    for (rgb::FaceId f : m.mesh.faces()) {
        for (int c = 0; c < 3; ++c) {
            const glm::dvec2 written = file.texcoords[file.triangle_texcoords[line][static_cast<std::size_t>(c)]];
            ASSERT_EQ(written, rgb::limit_uv(m.mesh, evaluator, f, c));
            differing += written != rgb::displayed_uv(m.mesh, evaluator, f, c);
        }
        ++line;
    }
    EXPECT_GT(differing, 0u) << "the limit UVs are not the displayed ones";
}

TEST(UvRoundTrip, TheSavedInterpolationResumesAndAnExplicitOneWins) {
    MeshWithUvs m = load(textured_grid(), rgb::UvInterpolation::Boundaries);
    rgbtest::set_level(m.mesh, 1);
    const std::string text = saved(m);
    EXPECT_NE(text.find("#rgb uv-interpolation boundaries\n"), std::string::npos);
    EXPECT_EQ(load(text).uvs->interpolation(), rgb::UvInterpolation::Boundaries);
    EXPECT_EQ(load(text, rgb::UvInterpolation::All).uvs->interpolation(), rgb::UvInterpolation::All);
}

TEST(UvRoundTrip, AMeshWithoutUvsKeepsTheStateWithoutTheSection) {
    rgb::Mesh mesh = build_mesh(read_obj_text(test::kOctahedron, "test.obj"));
    rgbtest::set_level(mesh, 1);
    EXPECT_EQ(format_obj(mesh, {}).find("base-uvs"), std::string::npos);
}

TEST(UvRoundTrip, ABadBaseUvsSectionIsRefusedNamingTheLine) {
    MeshWithUvs m = load(textured_grid());
    rgbtest::set_level(m.mesh, 1);
    const std::string text = saved(m);
    auto replaced = [&](const std::string& from, const std::string& to) {
        std::string t = text;
        t.replace(t.find(from), from.size(), to);
        return t;
    };
    // 12 used vt entries on each side of the seam.
    const ObjError count = test::load_error(replaced("#rgb section base-uvs 24\n", "#rgb section base-uvs 25\n"));
    EXPECT_NE(count.reason().find("announces 25 UVs but holds 24"), std::string::npos) << count.what();
    EXPECT_GT(count.line(), 0u);
    const ObjError option = test::load_error(replaced("#rgb uv-interpolation corners", "#rgb uv-interpolation smooth"));
    EXPECT_NE(option.reason().find("uv-interpolation must be"), std::string::npos) << option.what();
    const ObjError index = test::load_error(replaced("#rgb uv-faces 0 ", "#rgb uv-faces 24 "));
    EXPECT_NE(index.reason().find("UV index 24 of 24 UVs"), std::string::npos) << index.what();
}

TEST(UvRoundTrip, FacesWithoutVtStayWithoutAndAFaceWithSomeDropsTheUvs) {
    const std::string square = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";
    MeshWithUvs m = load(square + "f 2 4 3\n");
    ASSERT_NE(m.uvs, nullptr);
    EXPECT_EQ(m.uvs->channel().faces_without_uvs, std::vector<std::uint32_t>{1});
    rgbtest::set_level(m.mesh, 2);
    const LoadedMesh resumed = read_obj_text(saved(m), "test.obj");
    ASSERT_TRUE(resumed.adaptive);
    EXPECT_EQ(*resumed.base_uvs, m.uvs->channel());
    // The faces inside base face 1 are written without vt, the others with.
    const rgb::Mesh& mesh = *resumed.adaptive;
    std::size_t line = 0;
    for (rgb::FaceId f : mesh.faces()) {
        const bool textured = rgb::base_face_of(mesh, f) == 0;
        for (std::uint32_t t : resumed.triangle_texcoords[line]) EXPECT_EQ(t != kNoIndex, textured);
        ++line;
    }

    const LoadedMesh partial = read_obj_text(square + "f 2/2 4 3/3\n", "test.obj");
    std::vector<std::string> warnings;
    EXPECT_FALSE(base_uv_channel(partial, build_mesh(partial), warnings));
    EXPECT_TRUE(test::has_warning(warnings, "texture coordinates dropped"));
}

}  // namespace
}  // namespace rgbio
