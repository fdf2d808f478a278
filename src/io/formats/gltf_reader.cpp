#include "io/formats/gltf_reader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <tiny_gltf.h>

#include "io/files/file_text.h"
#include "io/formats/binary_value.h"
#include "io/formats/gltf_skin.h"
#include "io/obj/obj_error.h"

namespace rgbio {

namespace {

namespace fs = std::filesystem;

// Images are not decoded: only an external image's path is kept (the editor reads it as it reads
// an OBJ's map_Kd), and decoding would cost time and memory for nothing.
bool keep_image_undecoded(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) { return true; }

class GltfModel {
public:
    GltfModel(const tinygltf::Model& model, const std::string& path) : model_(model), path_(path) {}

    [[noreturn]] void fail(const std::string& reason) const { throw ObjError(ObjProblem::Malformed, path_, 0, reason); }

    // Accessor `index` as `count` elements of `components` doubles (normalized integers scaled to 0-1
    // as the spec says); checks that it lies in its buffer.
    std::vector<double> read(int index, int components, const char* what) const {
        const std::string name = std::string(what) + " accessor " + std::to_string(index);
        if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size()) fail("bad accessor: " + name + " does not exist");
        const tinygltf::Accessor& accessor = model_.accessors[static_cast<std::size_t>(index)];
        if (accessor.sparse.isSparse) fail("bad accessor: " + name + " is sparse, which rgbsub does not read");
        const int size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType));
        const int have = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
        if (size <= 0 || have < components) fail("bad accessor: " + name + " has the wrong type for its use");
        std::vector<double> values(accessor.count * static_cast<std::size_t>(components), 0.0);
        if (accessor.bufferView < 0) return values;  // the spec's all-zero accessor
        if (static_cast<std::size_t>(accessor.bufferView) >= model_.bufferViews.size()) fail("bad accessor: " + name + " names no buffer view");
        const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size()) fail("bad accessor: " + name + "'s view names no buffer");
        const std::vector<unsigned char>& buffer = model_.buffers[static_cast<std::size_t>(view.buffer)].data;
        const int stride = accessor.ByteStride(view);
        const std::size_t element = static_cast<std::size_t>(size) * static_cast<std::size_t>(have);
        if (stride <= 0 || static_cast<std::size_t>(stride) < element) fail("bad accessor: " + name + " has an invalid byte stride");
        const std::size_t start = view.byteOffset + accessor.byteOffset;
        const std::size_t end = accessor.count == 0 ? start : start + static_cast<std::size_t>(stride) * (accessor.count - 1) + element;
        if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset || end > view.byteOffset + view.byteLength ||
            end < start)
            fail("bad accessor: " + name + " reaches beyond its buffer (" + std::to_string(buffer.size()) + " bytes)");
        const unsigned char* bytes = buffer.data() + start;
        const auto copy = [&]<class T>(T, double scale, double low) {
            copy_values<T>(bytes, accessor.count, components, static_cast<std::size_t>(stride), scale, low, values.data());
        };
        // The spec's normalized integers: unsigned ones over their maximum, signed ones too, at least -1.
        const bool normalized = accessor.normalized;
        switch (accessor.componentType) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: copy(float(), 1.0, -HUGE_VAL); break;
            case TINYGLTF_COMPONENT_TYPE_DOUBLE: copy(double(), 1.0, -HUGE_VAL); break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: copy(std::uint8_t(), normalized ? 255.0 : 1.0, -HUGE_VAL); break;
            case TINYGLTF_COMPONENT_TYPE_BYTE: copy(std::int8_t(), normalized ? 127.0 : 1.0, normalized ? -1.0 : -HUGE_VAL); break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: copy(std::uint16_t(), normalized ? 65535.0 : 1.0, -HUGE_VAL); break;
            case TINYGLTF_COMPONENT_TYPE_SHORT: copy(std::int16_t(), normalized ? 32767.0 : 1.0, normalized ? -1.0 : -HUGE_VAL); break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: copy(std::uint32_t(), 1.0, -HUGE_VAL); break;
            case TINYGLTF_COMPONENT_TYPE_INT: copy(std::int32_t(), 1.0, -HUGE_VAL); break;
        }
        return values;
    }

    std::size_t count(int index) const { return model_.accessors[static_cast<std::size_t>(index)].count; }

private:
    // The components as stored, each over `scale` and at least `low` (x / 1 is x, NaN stays NaN).
    // Speed: one loop per component type, not a switch per value.
    template <class T>
    static void copy_values(const unsigned char* bytes, std::size_t count, int components, std::size_t stride, double scale, double low,
                            double* out) {
        for (std::size_t i = 0; i < count; ++i, bytes += stride)
            for (int c = 0; c < components; ++c) *out++ = std::max(binary_value<T>(bytes + static_cast<std::size_t>(c) * sizeof(T)) / scale, low);
    }
public:
    const std::string& path() const { return path_; }

private:
    const tinygltf::Model& model_;
    std::string path_;
};

glm::dmat4 local_transform(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3) m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4)
        m *= glm::mat4_cast(glm::normalize(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2])));
    if (node.scale.size() == 3) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

// What the reader collects while it walks the scene.
struct Collector {
    const tinygltf::Model& model;
    const GltfModel& data;
    ForeignMesh& out;
    std::vector<std::uint32_t> material_of;  // glTF material -> out.materials index
    std::size_t normals = 0, tangents = 0, extra_uvs = 0, skinned = 0, morphed = 0, lines_or_points = 0, alpha = 0;
    // The skin is kept while every primitive with triangles is skinned by one skin from nodes of one
    // transform (the weights of one vertex name the joints of one skeleton): `skin` is that one.
    int skin = -1;
    bool keep_skin = true;
    glm::dmat4 skin_transform{1.0};
    std::size_t unweighted = 0;
};

// The primitive's vertices' joint influences appended to c.out.influences, or the skin given up.
void add_influences(Collector& c, const tinygltf::Primitive& primitive, int skin, const glm::dmat4& transform, std::size_t first) {
    const auto joints = primitive.attributes.find("JOINTS_0"), weights = primitive.attributes.find("WEIGHTS_0");
    const bool skinned = skin >= 0 && joints != primitive.attributes.end() && weights != primitive.attributes.end();
    if (skinned && c.keep_skin && c.skin < 0) {
        c.skin = skin;
        c.skin_transform = transform;
    }
    c.keep_skin = c.keep_skin && skinned && c.skin == skin && c.skin_transform == transform;
    if (!c.keep_skin) return;
    const std::vector<double> j = c.data.read(joints->second, 4, "JOINTS_0");
    const std::vector<double> w = c.data.read(weights->second, 4, "WEIGHTS_0");
    if (j.size() != w.size() || j.size() / 4 != c.out.positions.size() - first)
        c.data.fail("JOINTS_0 and WEIGHTS_0 must have one element per vertex of their primitive");
    const std::vector<JointInfluences> influences =
        joint_influences(j, w, c.model.skins[static_cast<std::size_t>(skin)].joints.size(), c.data.path(), c.unweighted);
    c.out.influences.insert(c.out.influences.end(), influences.begin(), influences.end());
}

// The triangles of one primitive placed by `transform`, in group `group`.
void add_primitive(Collector& c, const tinygltf::Primitive& primitive, const glm::dmat4& transform, std::uint32_t group, int skin) {
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        ++c.lines_or_points;
        return;
    }
    const auto attribute = [&](const char* name) {
        const auto it = primitive.attributes.find(name);
        return it == primitive.attributes.end() ? -1 : it->second;
    };
    const int position = attribute("POSITION");
    if (position < 0) return;
    c.normals += attribute("NORMAL") >= 0;
    c.tangents += attribute("TANGENT") >= 0;
    c.extra_uvs += attribute("TEXCOORD_1") >= 0;
    c.skinned += attribute("JOINTS_0") >= 0 || attribute("WEIGHTS_0") >= 0;
    c.morphed += !primitive.targets.empty();

    ForeignMesh& out = c.out;
    const std::size_t first = out.positions.size();
    const std::vector<double> p = c.data.read(position, 3, "POSITION");
    const std::size_t n = p.size() / 3;
    out.positions.reserve(first + n);
    const bool identity = transform == glm::dmat4(1.0);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 x(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
        out.positions.push_back(identity ? x : glm::dvec3(transform * glm::dvec4(x, 1.0)));
    }
    const int texcoord = attribute("TEXCOORD_0");
    if (texcoord >= 0 || !out.vertex_uvs.empty()) {
        // A primitive without UVs among ones with them: its corners get (0, 0), as the writer does.
        out.vertex_uvs.resize(first, glm::dvec2(0.0));
        const std::vector<double> uv = texcoord >= 0 ? c.data.read(texcoord, 2, "TEXCOORD_0") : std::vector<double>();
        for (std::size_t i = 0; i < n; ++i)
            out.vertex_uvs.push_back(2 * i + 1 < uv.size() ? glm::dvec2(uv[2 * i], 1.0 - uv[2 * i + 1]) : glm::dvec2(0.0));
    }
    const int colour = attribute("COLOR_0");
    if (colour >= 0 || !out.colours.empty()) {
        out.colours.resize(first, glm::dvec3(1.0));
        const std::vector<double> rgb = colour >= 0 ? c.data.read(colour, 3, "COLOR_0") : std::vector<double>();
        if (colour >= 0) c.alpha += c.model.accessors[static_cast<std::size_t>(colour)].type == TINYGLTF_TYPE_VEC4;
        for (std::size_t i = 0; i < n; ++i)
            out.colours.push_back(3 * i + 2 < rgb.size() ? glm::dvec3(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]) : glm::dvec3(1.0));
    }
    add_influences(c, primitive, skin, transform, first);
    std::vector<std::uint32_t> indices;
    if (primitive.indices >= 0) {
        const std::vector<double> read = c.data.read(primitive.indices, 1, "indices");
        indices.reserve(read.size());
        for (double i : read) {
            if (i >= static_cast<double>(n)) c.data.fail("bad accessor: index " + std::to_string(static_cast<std::size_t>(i)) + " beyond the " +
                                                         std::to_string(n) + " vertices of its primitive");
            indices.push_back(static_cast<std::uint32_t>(first + static_cast<std::size_t>(i)));
        }
    } else {
        for (std::size_t i = 0; i < n; ++i) indices.push_back(static_cast<std::uint32_t>(first + i));
    }
    // A transform that mirrors turns the winding over: undone so outward stays outward.
    const bool mirrored = glm::determinant(glm::dmat3(transform)) < 0.0;
    const std::size_t faces_before = out.num_faces();
    out.corners.reserve(out.corners.size() + indices.size());
    out.face_start.reserve(out.face_start.size() + (mode == TINYGLTF_MODE_TRIANGLES ? indices.size() / 3 : indices.size()));
    const auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t d) { mirrored ? out.add_face(a, d, b) : out.add_face(a, b, d); };
    if (mode == TINYGLTF_MODE_TRIANGLES)
        for (std::size_t i = 0; i + 2 < indices.size(); i += 3) add(indices[i], indices[i + 1], indices[i + 2]);
    else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
        for (std::size_t i = 0; i + 2 < indices.size(); ++i)
            i % 2 == 0 ? add(indices[i], indices[i + 1], indices[i + 2]) : add(indices[i + 1], indices[i], indices[i + 2]);
    else
        for (std::size_t i = 1; i + 1 < indices.size(); ++i) add(indices[0], indices[i], indices[i + 1]);
    const std::size_t added = out.num_faces() - faces_before;
    const std::uint32_t material =
        primitive.material >= 0 && static_cast<std::size_t>(primitive.material) < c.material_of.size() ? c.material_of[static_cast<std::size_t>(primitive.material)] : kNoIndex;
    out.face_material.insert(out.face_material.end(), added, material);
    out.face_group.insert(out.face_group.end(), added, group);
}

void add_node(Collector& c, int index, const glm::dmat4& parent, std::vector<std::uint8_t>& on_path) {
    if (index < 0 || static_cast<std::size_t>(index) >= c.model.nodes.size()) c.data.fail("a scene names node " + std::to_string(index) + ", which does not exist");
    if (on_path[static_cast<std::size_t>(index)]) c.data.fail("node " + std::to_string(index) + " is its own ancestor");
    on_path[static_cast<std::size_t>(index)] = 1;
    const tinygltf::Node& node = c.model.nodes[static_cast<std::size_t>(index)];
    const glm::dmat4 transform = parent * local_transform(node);
    if (node.mesh >= 0) {
        if (static_cast<std::size_t>(node.mesh) >= c.model.meshes.size()) c.data.fail("node " + std::to_string(index) + " names a mesh that does not exist");
        const tinygltf::Mesh& mesh = c.model.meshes[static_cast<std::size_t>(node.mesh)];
        const std::uint32_t group = static_cast<std::uint32_t>(c.out.group_names.size());
        c.out.group_names.push_back(!node.name.empty() ? node.name : !mesh.name.empty() ? mesh.name : "mesh " + std::to_string(node.mesh + 1));
        if (node.skin >= 0 && static_cast<std::size_t>(node.skin) >= c.model.skins.size())
            c.data.fail("node " + std::to_string(index) + " names a skin that does not exist");
        for (const tinygltf::Primitive& primitive : mesh.primitives) add_primitive(c, primitive, transform, group, node.skin);
    }
    for (int child : node.children) add_node(c, child, transform, on_path);
    on_path[static_cast<std::size_t>(index)] = 0;
}

void read_materials(Collector& c, const fs::path& folder) {
    std::size_t embedded = 0;
    for (const tinygltf::Material& m : c.model.materials) {
        Material material;
        material.name = m.name;
        const std::vector<double>& factor = m.pbrMetallicRoughness.baseColorFactor;
        material.diffuse = factor.size() >= 3 ? glm::dvec3(factor[0], factor[1], factor[2]) : glm::dvec3(1.0);
        const int texture = m.pbrMetallicRoughness.baseColorTexture.index;
        if (texture >= 0 && static_cast<std::size_t>(texture) < c.model.textures.size()) {
            const int source = c.model.textures[static_cast<std::size_t>(texture)].source;
            if (source >= 0 && static_cast<std::size_t>(source) < c.model.images.size()) {
                const std::string& uri = c.model.images[static_cast<std::size_t>(source)].uri;
                if (uri.empty() || uri.starts_with("data:")) ++embedded;
                else material.diffuse_texture = (folder / uri).lexically_normal().string();
            }
        }
        c.material_of.push_back(static_cast<std::uint32_t>(c.out.materials.size()));
        c.out.materials.push_back(std::move(material));
    }
    name_materials(c.out.materials);
    if (embedded > 0) c.out.dropped.push_back(std::to_string(embedded) + " base-colour textures embedded in the file (only image files beside it are kept)");
}

// The skin that every mesh has, with its skeleton, into c.out; or no influences.
void finish_skin(Collector& c) {
    // Written joints are 16-bit (JOINTS_0 as unsigned short).
    const bool kept = c.skin >= 0 && c.keep_skin && c.unweighted == 0 && c.out.influences.size() == c.out.positions.size() &&
                      c.model.skins[static_cast<std::size_t>(c.skin)].joints.size() <= 65536;
    if (!kept) {
        c.out.influences.clear();
        return;
    }
    const tinygltf::Skin& skin = c.model.skins[static_cast<std::size_t>(c.skin)];
    const std::string name = "skin " + std::to_string(c.skin);
    for (int joint : skin.joints)
        if (joint < 0 || static_cast<std::size_t>(joint) >= c.model.nodes.size()) c.data.fail(name + " names joint node " + std::to_string(joint) + ", which does not exist");
    if (skin.skeleton >= 0 && static_cast<std::size_t>(skin.skeleton) >= c.model.nodes.size())
        c.data.fail(name + " names skeleton node " + std::to_string(skin.skeleton) + ", which does not exist");
    const std::vector<double> inverse_bind =
        skin.inverseBindMatrices >= 0 ? c.data.read(skin.inverseBindMatrices, 16, "inverseBindMatrices") : std::vector<double>();
    if (skin.inverseBindMatrices >= 0 && inverse_bind.size() < 16 * skin.joints.size())
        c.data.fail(name + " has fewer inverse bind matrices than joints");
    c.out.skeleton = std::make_shared<const Skeleton>(read_skeleton(c.model, c.skin, inverse_bind, c.skin_transform));
}

void name_dropped(const Collector& c) {
    const tinygltf::Model& m = c.model;
    note_dropped(c.out, c.normals, std::string("primitives' normals") + kNormalsRecomputed);
    note_dropped(c.out, c.tangents, "primitives' tangents");
    note_dropped(c.out, c.extra_uvs, "primitives' second texture coordinate sets (only TEXCOORD_0 is kept)");
    note_dropped(c.out, c.alpha, "primitives' colour alpha (COLOR_0 keeps red, green and blue)");
    if (c.out.skeleton) {
        note_dropped(c.out, m.skins.size() - 1, "skins besides the one of the meshes");
    } else {
        note_dropped(c.out, c.skinned,
                     c.unweighted > 0 ? "skinned primitives' joints and weights (JOINTS_0/WEIGHTS_0): " + std::to_string(c.unweighted) +
                                            " of their vertices have no weight"
                                      : "skinned primitives' joints and weights (JOINTS_0/WEIGHTS_0): a skin is kept only when every "
                                        "mesh is skinned by the same one");
        note_dropped(c.out, m.skins.size(), "skins");
    }
    note_dropped(c.out, c.morphed, "primitives' morph targets");
    note_dropped(c.out, m.animations.size(), "animations");
    note_dropped(c.out, m.cameras.size(), "cameras");
    note_dropped(c.out, m.lights.size(), "lights");
    note_dropped(c.out, c.lines_or_points, "primitives of points or lines");
}

}  // namespace

ForeignMesh read_gltf_mesh(const std::string& path) {
    const FileText text = read_file_text(path);
    const std::string_view bytes = text.view();
    if (bytes.size() > UINT32_MAX) throw ObjError(ObjProblem::Malformed, path, 0, "the file is larger than glTF's 4 GiB");
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keep_image_undecoded, nullptr);
    tinygltf::Model model;
    std::string error, warning;
    const fs::path folder = fs::path(path).parent_path();
    const bool binary = bytes.starts_with("glTF");
    const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
                                                         static_cast<unsigned int>(bytes.size()), folder.string())
                           : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), static_cast<unsigned int>(bytes.size()),
                                                        folder.string());
    text.check_not_shrunk();
    if (!ok) {
        error = trimmed_message(error);
        throw ObjError(ObjProblem::Malformed, path, 0, "not a readable glTF file: " + (error.empty() ? std::string("tinygltf refused it") : error));
    }
    if (!model.asset.version.starts_with("2"))
        throw ObjError(ObjProblem::Malformed, path, 0, "a glTF " + model.asset.version + " file: rgbsub reads glTF 2.0 (convert it, e.g. with Blender)");
    ForeignMesh out;
    GltfModel data(model, path);
    Collector c{model, data, out, {}};
    read_materials(c, folder);
    std::vector<std::uint8_t> on_path(model.nodes.size(), 0);
    const glm::dmat4 identity(1.0);
    if (!model.scenes.empty()) {
        const std::size_t scene = model.defaultScene >= 0 && static_cast<std::size_t>(model.defaultScene) < model.scenes.size()
                                      ? static_cast<std::size_t>(model.defaultScene) : 0;
        for (int node : model.scenes[scene].nodes) add_node(c, node, identity, on_path);
        if (model.scenes.size() > 1) out.dropped.push_back(std::to_string(model.scenes.size() - 1) + " scenes besides the default one");
    } else {
        // No scene: the meshes as they are, one group each (the spec leaves such a file to the application).
        for (std::size_t m = 0; m < model.meshes.size(); ++m) {
            out.group_names.push_back(model.meshes[m].name.empty() ? "mesh " + std::to_string(m + 1) : model.meshes[m].name);
            for (const tinygltf::Primitive& primitive : model.meshes[m].primitives)
                add_primitive(c, primitive, identity, static_cast<std::uint32_t>(m), -1);
        }
    }
    finish_skin(c);
    name_dropped(c);
    drop_idle_labels(out);
    return out;
}

}  // namespace rgbio
