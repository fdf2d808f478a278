#include "io/gltf/gltf_writer.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <tiny_gltf.h>

#include "io/files/atomic_file.h"
#include "io/files/save_target.h"
#include "io/obj/obj_error.h"
#include "io/obj/printable_text.h"

namespace rgbio {

namespace {

namespace fs = std::filesystem;

// A URI reference for a file path: '/'-separated, with every byte outside the unreserved set
// percent-encoded.
std::string path_uri(const fs::path& path) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string uri;
    for (const char c : path.generic_string()) {
        const auto byte = static_cast<unsigned char>(c);
        if (std::isalnum(byte) || std::strchr("-._~/", c)) {
            uri += c;
        } else {
            uri += '%';
            uri += kHex[byte >> 4];
            uri += kHex[byte & 15];
        }
    }
    return uri;
}

// glTF vertices: one per distinct (vertex, texture coordinate) corner, in order of first use.
struct GltfVertices {
    std::vector<std::uint32_t> position;  // per glTF vertex: the mesh vertex
    std::vector<std::uint32_t> texcoord;  // per glTF vertex: the table entry, or kNoIndex
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

// The glTF vertices of each mesh vertex are chained (first by mesh vertex, next by glTF vertex): a
// vertex has one per texture coordinate it takes, so the chains are short, and flat arrays cost a
// fraction of a hash table over every corner (a large share of writing a million triangles).
GltfVertices unweld(const GltfMesh& mesh) {
    GltfVertices out;
    std::vector<std::uint32_t> first(mesh.positions.size(), kNoIndex), next;
    out.triangles.reserve(mesh.triangles.size());
    out.position.reserve(mesh.positions.size());
    out.texcoord.reserve(mesh.positions.size());
    next.reserve(mesh.positions.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        std::array<std::uint32_t, 3> corners;
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t v = mesh.triangles[t][i];
            const std::uint32_t uv = mesh.triangle_texcoords.empty() ? kNoIndex : mesh.triangle_texcoords[t][i];
            std::uint32_t g = first[v];
            while (g != kNoIndex && out.texcoord[g] != uv) g = next[g];
            if (g == kNoIndex) {
                g = static_cast<std::uint32_t>(out.position.size());
                out.position.push_back(v);
                out.texcoord.push_back(uv);
                next.push_back(first[v]);
                first[v] = g;
            }
            corners[i] = g;
        }
        out.triangles.push_back(corners);
    }
    return out;
}

class ModelBuilder {
public:
    // Appends raw values to the buffer as a view (4-byte aligned: every value here is 4 bytes, or
    // 2 in groups of four).
    template <class T>
    int add_view(const std::vector<T>& values, int target) {
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = bytes_.size();
        view.byteLength = values.size() * sizeof(T);
        view.target = target;
        const auto* begin = reinterpret_cast<const unsigned char*>(values.data());
        bytes_.insert(bytes_.end(), begin, begin + view.byteLength);
        model.bufferViews.push_back(view);
        return static_cast<int>(model.bufferViews.size() - 1);
    }

    int add_accessor(int view, int component_type, int type, std::size_t count, std::vector<double> min = {},
                     std::vector<double> max = {}) {
        tinygltf::Accessor accessor;
        accessor.bufferView = view;
        accessor.componentType = component_type;
        accessor.type = type;
        accessor.count = count;
        accessor.minValues = std::move(min);
        accessor.maxValues = std::move(max);
        model.accessors.push_back(accessor);
        return static_cast<int>(model.accessors.size() - 1);
    }

    // Float vectors of N components, with the bounds POSITION needs.
    template <int N, class Vec>
    int add_floats(const std::vector<Vec>& values, int type, bool bounds) {
        std::vector<float> flat;
        flat.reserve(N * values.size());
        std::vector<double> lo(N, HUGE_VAL), hi(N, -HUGE_VAL);
        for (const Vec& v : values)
            for (int i = 0; i < N; ++i) {
                const float x = static_cast<float>(v[i]);
                flat.push_back(x);
                lo[i] = std::min(lo[i], double(x));
                hi[i] = std::max(hi[i], double(x));
            }
        const int view = add_view(flat, TINYGLTF_TARGET_ARRAY_BUFFER);
        return bounds ? add_accessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, type, values.size(), lo, hi)
                      : add_accessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, type, values.size());
    }

    void finish() {
        tinygltf::Buffer buffer;
        buffer.data = std::move(bytes_);
        model.buffers.push_back(std::move(buffer));
    }

    tinygltf::Model model;

private:
    std::vector<unsigned char> bytes_;
};

// glTF strings are UTF-8 (JSON): a name that is not keeps its bytes as \xNN text.
bool is_utf8(std::string_view text) {
    for (std::size_t i = 0; i < text.size();) {
        const auto lead = static_cast<unsigned char>(text[i]);
        const std::size_t length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
        if (length == 0 || i + length > text.size()) return false;
        for (std::size_t k = 1; k < length; ++k)
            if ((static_cast<unsigned char>(text[i + k]) >> 6) != 0x2) return false;
        i += length;
    }
    return true;
}
std::string utf8_name(const std::string& name) {
    if (is_utf8(name)) return name;
    const std::string quoted = quoted_file_text(name, name.size());
    return quoted.substr(1, quoted.size() - 2);
}
// A base colour factor must be a number in [0, 1]: clamped, and 1 for one that is not a number.
double colour_factor(double x) { return std::isnan(x) ? 1.0 : std::clamp(x, 0.0, 1.0); }
bool is_colour_factor(double x) { return x >= 0.0 && x <= 1.0; }
// A normal that normalizes to a unit vector of floats, or nothing.
std::optional<glm::dvec3> unit_normal(const glm::dvec3& n) {
    const double length = glm::length(n);
    if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
    const glm::dvec3 unit = n / length;
    if (!std::isfinite(unit.x) || !std::isfinite(unit.y) || !std::isfinite(unit.z)) return std::nullopt;
    return unit;
}

// One glTF material per mesh material; textures share images by path.
void add_materials(const GltfMesh& mesh, const fs::path& output_folder, tinygltf::Model& model) {
    std::map<std::string, int> texture_of_path;
    for (const Material& m : mesh.materials) {
        tinygltf::Material material;
        material.name = utf8_name(m.name);
        material.pbrMetallicRoughness.metallicFactor = 0.0;  // OBJ materials are dielectrics
        material.pbrMetallicRoughness.roughnessFactor = 1.0;
        if (m.diffuse_texture.empty()) {
            material.pbrMetallicRoughness.baseColorFactor = {colour_factor(m.diffuse.r), colour_factor(m.diffuse.g), colour_factor(m.diffuse.b), 1.0};
        } else {
            auto [it, inserted] = texture_of_path.try_emplace(m.diffuse_texture, static_cast<int>(model.textures.size()));
            if (inserted) {
                tinygltf::Image image;
                image.uri = path_uri(fs::absolute(m.diffuse_texture).lexically_relative(fs::absolute(output_folder)));
                model.images.push_back(image);
                tinygltf::Texture texture;
                texture.source = static_cast<int>(model.images.size() - 1);
                model.textures.push_back(texture);
            }
            material.pbrMetallicRoughness.baseColorTexture.index = it->second;
        }
        model.materials.push_back(material);
    }
}

}  // namespace

std::vector<std::uint32_t> material_indices(const FaceLabels& face_materials, const std::vector<Material>& materials) {
    std::map<std::string, std::uint32_t, std::less<>> index;
    for (std::uint32_t m = 0; m < materials.size(); ++m) index.try_emplace(materials[m].name, m);
    std::vector<std::uint32_t> of_name(face_materials.names.size(), kNoIndex);
    for (std::size_t n = 0; n < of_name.size(); ++n)
        if (const auto it = index.find(face_materials.names[n]); it != index.end()) of_name[n] = it->second;
    std::vector<std::uint32_t> result;
    result.reserve(face_materials.of_triangle.size());
    for (std::uint32_t name : face_materials.of_triangle) result.push_back(name == kNoIndex ? kNoIndex : of_name[name]);
    return result;
}

std::vector<std::string> gltf_material_repairs(std::span<const Material> materials) {
    std::vector<std::string> warnings;
    std::size_t names = 0, colours = 0;
    const Material* first_name = nullptr;
    const Material* first_colour = nullptr;
    for (const Material& m : materials) {
        if (!is_utf8(m.name) && names++ == 0) first_name = &m;
        const bool in_range = is_colour_factor(m.diffuse.r) && is_colour_factor(m.diffuse.g) && is_colour_factor(m.diffuse.b);
        if (m.diffuse_texture.empty() && !in_range && colours++ == 0) first_colour = &m;
    }
    if (names > 0)
        warnings.push_back(std::to_string(names) + " material names are not UTF-8, which glTF needs; written with \\xNN for their other bytes, the first " +
                           quoted_file_text(first_name->name));
    if (colours > 0)
        warnings.push_back(std::to_string(colours) + " materials have a diffuse colour (Kd) outside 0..1, clamped for glTF's baseColorFactor, the first " +
                           quoted_file_text(first_colour->name));
    return warnings;
}

std::optional<std::string> gltf_normal_repair(const GltfMesh& mesh) {
    const auto normals = static_cast<std::size_t>(std::count_if(mesh.normals.begin(), mesh.normals.end(), [](const glm::dvec3& n) { return !unit_normal(n); }));
    if (normals == 0) return std::nullopt;
    return std::to_string(normals) + " vertices have no normal (only degenerate faces around them): written as +z";
}

namespace {

// The mesh's glTF vertices and one primitive per material in material order, then the triangles
// without one, every primitive indexed.
tinygltf::Mesh add_mesh(ModelBuilder& builder, const GltfMesh& mesh) {
    const GltfVertices vertices = unweld(mesh);
    tinygltf::Primitive base;
    base.mode = TINYGLTF_MODE_TRIANGLES;
    std::vector<glm::dvec3> positions;
    for (std::uint32_t v : vertices.position) positions.push_back(mesh.positions[v]);
    base.attributes["POSITION"] = builder.add_floats<3>(positions, TINYGLTF_TYPE_VEC3, true);
    if (!mesh.normals.empty()) {
        std::vector<glm::dvec3> normals;
        for (std::uint32_t v : vertices.position) {
            // A degenerate face's point has no normal: +z stands in (gltf_normal_repair warns).
            normals.push_back(unit_normal(mesh.normals[v]).value_or(glm::dvec3(0.0, 0.0, 1.0)));
        }
        base.attributes["NORMAL"] = builder.add_floats<3>(normals, TINYGLTF_TYPE_VEC3, false);
    }
    if (!mesh.colours.empty()) {
        std::vector<glm::dvec3> colours;
        for (std::uint32_t v : vertices.position) colours.push_back(mesh.colours[v]);
        base.attributes["COLOR_0"] = builder.add_floats<3>(colours, TINYGLTF_TYPE_VEC3, false);
    }
    if (!mesh.influences.empty()) {
        std::vector<std::uint16_t> joints;
        std::vector<float> weights;
        for (std::uint32_t v : vertices.position) {
            const JointInfluences& in = mesh.influences[v];
            for (std::uint32_t j : in.joints) joints.push_back(static_cast<std::uint16_t>(j));
            // The heaviest takes what the others leave of 1, so that the floats written sum to 1
            // within the last bit (viewers and the validator check the sum).
            double rest = 0.0;
            for (std::size_t k = 1; k < kMaxInfluences; ++k) rest += static_cast<double>(static_cast<float>(in.weights[k]));
            weights.push_back(static_cast<float>(1.0 - rest));
            for (std::size_t k = 1; k < kMaxInfluences; ++k) weights.push_back(static_cast<float>(in.weights[k]));
        }
        base.attributes["JOINTS_0"] = builder.add_accessor(builder.add_view(joints, TINYGLTF_TARGET_ARRAY_BUFFER),
                                                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC4, vertices.position.size());
        base.attributes["WEIGHTS_0"] = builder.add_accessor(builder.add_view(weights, TINYGLTF_TARGET_ARRAY_BUFFER),
                                                            TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, vertices.position.size());
    }
    if (!mesh.triangle_texcoords.empty()) {
        std::vector<glm::dvec2> texcoords;
        for (std::uint32_t uv : vertices.texcoord)
            texcoords.push_back(uv == kNoIndex ? glm::dvec2(0.0) : glm::dvec2(mesh.texcoords[uv].x, 1.0 - mesh.texcoords[uv].y));
        base.attributes["TEXCOORD_0"] = builder.add_floats<2>(texcoords, TINYGLTF_TYPE_VEC2, false);
    }
    std::map<std::uint32_t, std::vector<std::uint32_t>> indices_of_material;
    for (std::size_t t = 0; t < vertices.triangles.size(); ++t) {
        const std::uint32_t material = mesh.triangle_materials.empty() ? kNoIndex : mesh.triangle_materials[t];
        auto& indices = indices_of_material[material];
        indices.insert(indices.end(), vertices.triangles[t].begin(), vertices.triangles[t].end());
    }
    tinygltf::Mesh gltf_mesh;
    for (const auto& [material, indices] : indices_of_material) {
        tinygltf::Primitive primitive = base;
        primitive.indices = builder.add_accessor(builder.add_view(indices, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                                                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, indices.size());
        primitive.material = material == kNoIndex ? -1 : static_cast<int>(material);
        gltf_mesh.primitives.push_back(primitive);
    }
    return gltf_mesh;
}

// The skin, its joints the skeleton's nodes as they will be numbered: after the `first_node` nodes
// of the levels.
void add_skin(ModelBuilder& builder, const Skeleton& skeleton, int first_node) {
    tinygltf::Skin skin;
    skin.name = utf8_name(skeleton.name);
    for (std::uint32_t joint : skeleton.joints) skin.joints.push_back(first_node + static_cast<int>(joint));
    if (skeleton.root >= 0) skin.skeleton = first_node + static_cast<int>(skeleton.root);
    std::vector<float> matrices;
    for (const glm::dmat4& m : skeleton.inverse_bind_matrices)
        for (int column = 0; column < 4; ++column)
            for (int row = 0; row < 4; ++row) matrices.push_back(static_cast<float>(m[column][row]));
    // Inverse bind matrices are no vertex data: their view has no target.
    skin.inverseBindMatrices = builder.add_accessor(builder.add_view(matrices, 0), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_MAT4,
                                                    skeleton.inverse_bind_matrices.size());
    builder.model.skins.push_back(std::move(skin));
}

// The skeleton's nodes after the levels' nodes, with the names and transforms of the file read.
void add_skeleton_nodes(const Skeleton& skeleton, tinygltf::Model& model) {
    const int first = static_cast<int>(model.nodes.size());
    for (const SkeletonNode& s : skeleton.nodes) {
        tinygltf::Node node;
        node.name = utf8_name(s.name);
        node.matrix = s.matrix;
        node.translation = s.translation;
        node.rotation = s.rotation;
        node.scale = s.scale;
        for (std::uint32_t c : s.children) node.children.push_back(first + static_cast<int>(c));
        model.nodes.push_back(std::move(node));
    }
}

}  // namespace

std::string format_gltf_lods(std::span<const GltfMesh> levels, std::span<const double> coverage, GltfContainer container,
                             const std::string& output_folder) {
    if (levels.empty() || (levels.size() > 1 && coverage.size() != levels.size()))
        throw std::invalid_argument("format_gltf_lods: one or more levels, with a screen coverage each when several");
    ModelBuilder builder;
    for (const GltfMesh& level : levels) builder.model.meshes.push_back(add_mesh(builder, level));
    const Skeleton* skeleton = levels[0].skeleton.get();
    if (skeleton) add_skin(builder, *skeleton, static_cast<int>(levels.size()));
    builder.finish();

    tinygltf::Model& model = builder.model;
    model.asset.version = "2.0";
    model.asset.generator = "rgbsub";
    add_materials(levels[0], output_folder, model);  // every level has the materials of the same input
    for (std::size_t i = 0; i < levels.size(); ++i) {
        tinygltf::Node node;
        node.mesh = static_cast<int>(i);
        if (skeleton) node.skin = 0;
        if (levels.size() > 1) node.name = "LOD" + std::to_string(i);
        model.nodes.push_back(node);
    }
    if (levels.size() > 1) {
        // MSFT_lod: the scene's node shows LOD0 and names the coarser levels' nodes, which are in no
        // scene; MSFT_screencoverage gives per level the screen coverage down to which it is shown.
        tinygltf::Value::Array ids, coverages;
        for (std::size_t i = 1; i < levels.size(); ++i) ids.emplace_back(static_cast<int>(i));
        for (double c : coverage) coverages.emplace_back(c);
        tinygltf::Value::Object lod{{"ids", tinygltf::Value(ids)}};
        model.nodes[0].extensions["MSFT_lod"] = tinygltf::Value(lod);
        tinygltf::Value::Object extras{{"MSFT_screencoverage", tinygltf::Value(coverages)}};
        model.nodes[0].extras = tinygltf::Value(extras);
        model.extensionsUsed.push_back("MSFT_lod");
    }
    if (skeleton) add_skeleton_nodes(*skeleton, model);
    tinygltf::Scene scene;
    scene.nodes.push_back(0);
    if (skeleton) {
        // The skeleton's roots: its nodes that are no other's child.
        std::vector<std::uint8_t> child(skeleton->nodes.size(), 0);
        for (const SkeletonNode& node : skeleton->nodes)
            for (std::uint32_t c : node.children) child[c] = 1;
        for (std::size_t n = 0; n < child.size(); ++n)
            if (!child[n]) scene.nodes.push_back(static_cast<int>(levels.size() + n));
    }
    model.scenes.push_back(scene);
    model.defaultScene = 0;

    tinygltf::TinyGLTF writer;
    writer.SetImageWriter(nullptr, nullptr);  // images are referenced by path, never re-encoded
    std::ostringstream out;
    const bool binary = container == GltfContainer::Binary;
    if (!writer.WriteGltfSceneToStream(&model, out, !binary, binary)) throw SaveError("cannot encode the glTF scene");
    return out.str();
}

std::string format_gltf(const GltfMesh& mesh, GltfContainer container, const std::string& output_folder) {
    return format_gltf_lods(std::span<const GltfMesh>(&mesh, 1), {}, container, output_folder);
}

void save_gltf_lods(std::span<const GltfMesh> levels, std::span<const double> coverage, const std::string& path) {
    const bool binary = has_extension(path, ".glb");
    // Image paths from the real file's folder: saved through a symbolic link, it lives where the link leads.
    const std::string folder = resolve_save_target(path).folder;
    write_file_atomically(path, format_gltf_lods(levels, coverage, binary ? GltfContainer::Binary : GltfContainer::Json, folder));
}

void save_gltf(const GltfMesh& mesh, const std::string& path) { save_gltf_lods(std::span<const GltfMesh>(&mesh, 1), {}, path); }

}  // namespace rgbio
