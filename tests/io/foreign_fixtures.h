#pragma once
// Small files of other formats written byte by byte in the tests (no library that rgbsub reads them
// with is involved in writing them): binary values, a glTF binary container, PLY and STL bodies.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace rgbio::test {

// Appends v's bytes, little endian (or big endian when asked).
template <class T>
void put(std::string& out, T v, bool big_endian = false) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &v, sizeof(T));
    if (big_endian == (std::endian::native == std::endian::little)) std::reverse(bytes, bytes + sizeof(T));
    out.append(bytes, sizeof(T));
}

// A .glb of the JSON chunk and the binary chunk (each padded to 4 bytes as the spec says).
inline std::string glb_file(std::string json, std::string bin) {
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin += '\0';
    std::string out = "glTF";
    put<std::uint32_t>(out, 2);
    put<std::uint32_t>(out, static_cast<std::uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(json.size()));
    out += "JSON" + json;
    if (!bin.empty()) {
        put<std::uint32_t>(out, static_cast<std::uint32_t>(bin.size()));
        out += std::string("BIN\0", 4) + bin;
    }
    return out;
}

// The bytes of value arrays, and the glTF JSON of their buffer views and accessors, for a .glb.
struct GlbBuffer {
    std::string bytes, views, accessors;
    int count = 0;
    // An accessor over the floats (`type` VEC3, VEC2, ...; `components` per element).
    int add_floats(const std::vector<float>& values, const char* type, int components) {
        return add(values, type, components, 5126);
    }
    int add_indices(const std::vector<std::uint32_t>& values) { return add(values, "SCALAR", 1, 5125); }
    // An accessor over values of any component type (5121 unsigned byte, 5123 unsigned short, ...).
    template <class T>
    int add(const std::vector<T>& values, const char* type, int components, int component_type, bool normalized = false) {
        const std::size_t offset = bytes.size();
        for (T v : values) put<T>(bytes, v);
        while (bytes.size() % 4) bytes += '\0';  // the next view starts aligned
        const std::string comma = count > 0 ? "," : "";
        views += comma + R"({"buffer":0,"byteOffset":)" + std::to_string(offset) + R"(,"byteLength":)" + std::to_string(values.size() * sizeof(T)) + "}";
        accessors += comma + R"({"bufferView":)" + std::to_string(count) + R"(,"componentType":)" + std::to_string(component_type) +
                     (normalized ? R"(,"normalized":true)" : "") + R"(,"count":)" + std::to_string(values.size() / static_cast<std::size_t>(components)) +
                     R"(,"type":")" + type + "\"}";
        return count++;
    }
    std::string json(const std::string& rest) const {
        return R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":)" + std::to_string(bytes.size()) + R"(}],"bufferViews":[)" + views +
               R"(],"accessors":[)" + accessors + "]," + rest + "}";
    }
    std::string file(const std::string& rest) const { return glb_file(json(rest), bytes); }
};

// A binary STL of the given triangles (9 floats each), normals left zero.
inline std::string binary_stl(const std::vector<std::array<float, 9>>& triangles) {
    std::string out(80, ' ');
    put<std::uint32_t>(out, static_cast<std::uint32_t>(triangles.size()));
    for (const auto& t : triangles) {
        for (int i = 0; i < 3; ++i) put<float>(out, 0.0f);
        for (float x : t) put<float>(out, x);
        put<std::uint16_t>(out, 0);
    }
    return out;
}

// A tetrahedron in binary PLY, little endian doubles with byte colours, then big endian floats.
inline std::string binary_tetrahedron_ply(bool big_endian, bool doubles, const std::vector<glm::dvec3>& p) {
    std::string out = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") + " 1.0\nelement vertex 4\n";
    for (const char* axis : {"x", "y", "z"}) out += std::string("property ") + (doubles ? "double " : "float ") + axis + "\n";
    out += "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 4\nproperty list uchar uint vertex_indices\n"
           "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
    for (std::size_t i = 0; i < p.size(); ++i) {
        for (int c = 0; c < 3; ++c) doubles ? put<double>(out, p[i][c], big_endian) : put<float>(out, static_cast<float>(p[i][c]), big_endian);
        for (std::uint8_t c : {std::uint8_t(255), std::uint8_t(128), std::uint8_t(i)}) put<std::uint8_t>(out, c);
    }
    for (std::array<std::uint32_t, 3> f : {std::array<std::uint32_t, 3>{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}) {
        put<std::uint8_t>(out, 3);
        for (std::uint32_t v : f) put<std::uint32_t>(out, v, big_endian);
    }
    put<std::int32_t>(out, 0, big_endian);
    put<std::int32_t>(out, 1, big_endian);
    return out;
}

}  // namespace rgbio::test
