// Every file of Debian's assimp-testmodels in the formats rgbsub claims to read besides OBJ (glTF,
// PLY, STL, FBX, COLLADA, 3DS, OFF) of at most kMaxBytes either loads into a valid mesh (triangles
// over existing vertices, per-triangle data of the right length) or is refused with an ObjError
// naming the file and a reason; none crashes or throws anything else. The size bound keeps the test
// well under a second (the larger files are a few big FBX and PLY scans that say nothing new).
#include <algorithm>
#include <filesystem>
#include <set>

#include <gtest/gtest.h>

#include "io/mesh_reader.h"
#include "io/obj/obj_error.h"

namespace rgbio {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = "/usr/share/assimp/models";
constexpr std::uintmax_t kMaxBytes = 200 * 1024;

std::vector<fs::path> corpus_files() {
    const std::set<std::string> claimed = {".gltf", ".glb", ".ply", ".stl", ".fbx", ".dae", ".3ds", ".off"};
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(kCorpus)) {
        std::string extension = entry.path().extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (entry.is_regular_file() && claimed.count(extension) && entry.file_size() <= kMaxBytes) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());  // the directory's order is the file system's
    return files;
}

TEST(ForeignCorpus, EveryFileLoadsOrIsRefusedWithAReason) {
    ASSERT_TRUE(fs::is_directory(kCorpus)) << "install Debian's assimp-testmodels";
    const std::vector<fs::path> files = corpus_files();
    ASSERT_GT(files.size(), 50u);
    std::size_t loaded = 0, refused = 0;
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        try {
            const LoadedMesh mesh = read_mesh_file(file.string());
            ASSERT_FALSE(mesh.triangles.empty());
            for (const rgb::Triangle& t : mesh.triangles)
                for (std::uint32_t v : t) ASSERT_LT(v, mesh.positions.size());
            EXPECT_TRUE(mesh.triangle_texcoords.empty() || mesh.triangle_texcoords.size() == mesh.triangles.size());
            EXPECT_TRUE(mesh.colours.empty() || mesh.colours.size() == mesh.positions.size());
            EXPECT_TRUE(mesh.face_materials.of_triangle.empty() || mesh.face_materials.of_triangle.size() == mesh.triangles.size());
            ++loaded;
        } catch (const ObjError& e) {
            EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
            EXPECT_FALSE(e.reason().empty());
            ++refused;
        }
    }
    // Most of the corpus is meant to load (the rest are its invalid files, glTF 1.0, point clouds and
    // primitive modes without triangles): a reader that refused everything would pass the above.
    EXPECT_GT(loaded, 2 * refused) << loaded << " loaded, " << refused << " refused";
}

}  // namespace
}  // namespace rgbio
