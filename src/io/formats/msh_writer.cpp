#include "io/formats/format_writers.h"

#include <algorithm>

#include <glm/common.hpp>

#include "io/files/atomic_file.h"
#include "io/obj/number_format.h"

namespace rgbio {

namespace {

// The numbers of one MSH file, in the encoding asked for, so that both encodings come from one
// description of the sections. ASCII: text, a record per line, its numbers separated by spaces
// (doubles in shortest round-trip decimals). Binary (file-type 1, data-size 8): each number as the
// spec's C type in this machine's byte order, which the int 1 after the format line tells readers:
// size_t (8 bytes) for counts and the node and element tags of $Nodes and $Elements, int for
// entity dimensions, tags and types and for the element tags of $ElementData, double for coordinates
// and values. Section names and $ElementData's tag lines are text in both.
class MshNumbers {
public:
    MshNumbers(AtomicFileWriter& file, MshEncoding encoding) : file_(file), out_(file.buffer()), binary_(encoding == MshEncoding::Binary) {}

    void size(std::uint64_t x) { binary_ ? append_bytes(out_, x) : text(x); }
    void integer(std::int32_t x) { binary_ ? append_bytes(out_, x) : text(static_cast<std::uint64_t>(x)); }
    // In ASCII with a space before it, even first in its record (as the coordinate lines have always been).
    void real(double x) {
        binary_ ? append_bytes(out_, x) : append_double(out_, x);
        first_ = false;
    }
    // Ends a record: ASCII's line end; binary records run on.
    void end_record() {
        if (!binary_) out_ += '\n';
        first_ = true;
        file_.flush_if_full();
    }
    // "$Name\n" opens a section; "$EndName\n" closes it, on a line of its own after binary data.
    void begin(const char* name) { out_ += std::string("$") + name + "\n"; }
    void end(const char* name) { out_ += std::string(binary_ ? "\n$End" : "$End") + name + "\n"; }
    std::string& text_lines() { return out_; }

private:
    void text(std::uint64_t x) {
        first_ ? append_digits(out_, x) : append_integer(out_, x);
        first_ = false;
    }

    AtomicFileWriter& file_;
    std::string& out_;
    const bool binary_;
    bool first_ = true;
};

// $Nodes' or $Elements' header with one block of `count` entities tagged 1..count (blocks, count, min
// and max tag), then that block's: on surface entity 1 (dimension 2), `kind` (0: nodes without
// parametric coordinates; 2: 3-node triangles), count.
void one_block_header(MshNumbers& msh, std::uint64_t count, std::int32_t kind) {
    for (std::uint64_t header : {std::uint64_t{1}, count, std::uint64_t{1}, count}) msh.size(header);
    msh.end_record();
    for (std::int32_t header : {2, 1, kind}) msh.integer(header);
    msh.size(count);
    msh.end_record();
}

// One $ElementData view: a scalar per element, elements numbered from 1, step 0.
template <class Value>
void write_element_data(MshNumbers& msh, const char* name, std::size_t count, Value value) {
    msh.begin("ElementData");
    msh.text_lines() += std::string("1\n\"") + name + "\"\n1\n0\n3\n0\n1\n" + std::to_string(count) + "\n";
    for (std::size_t t = 0; t < count; ++t) {
        msh.integer(static_cast<std::int32_t>(t + 1));
        value(t);
        msh.end_record();
    }
    msh.end("ElementData");
}

}  // namespace

void save_msh(const ExportMesh& mesh, const std::string& path, MshEncoding encoding) {
    AtomicFileWriter file(path);
    MshNumbers msh(file, encoding);
    const std::size_t n = mesh.positions.size(), m = mesh.triangles.size();
    msh.begin("MeshFormat");
    msh.text_lines() += encoding == MshEncoding::Binary ? "4.1 1 8\n" : "4.1 0 8\n";
    if (encoding == MshEncoding::Binary) msh.integer(1);  // the byte order
    msh.end("MeshFormat");
    // One surface entity (tag 1) holding every node and triangle, with the mesh's bounding box, no
    // physical tags and no bounding curves.
    glm::dvec3 lo(0.0), hi(0.0);
    if (n > 0) lo = hi = mesh.positions[0];
    for (const glm::dvec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    msh.begin("Entities");
    for (std::uint64_t count : {0, 0, 1, 0}) msh.size(count);  // points, curves, surfaces, volumes
    msh.end_record();
    msh.integer(1);
    for (const glm::dvec3& corner : {lo, hi})
        for (int i = 0; i < 3; ++i) msh.real(corner[i]);
    msh.size(0);
    msh.size(0);
    msh.end_record();
    msh.end("Entities");
    // The node tags, then the coordinates.
    msh.begin("Nodes");
    one_block_header(msh, n, 0);
    for (std::size_t v = 0; v < n; ++v) {
        msh.size(v + 1);
        msh.end_record();
    }
    for (const glm::dvec3& p : mesh.positions) {
        for (int i = 0; i < 3; ++i) msh.real(p[i]);
        msh.end_record();
    }
    msh.end("Nodes");
    // Each triangle's tag and its nodes' tags.
    msh.begin("Elements");
    one_block_header(msh, m, 2);
    for (std::size_t t = 0; t < m; ++t) {
        msh.size(t + 1);
        for (std::uint32_t v : mesh.triangles[t]) msh.size(std::uint64_t{v} + 1);
        msh.end_record();
    }
    msh.end("Elements");
    // Values are doubles in binary files (data-size 8); the ASCII ones write level and colour as integers.
    const auto whole = [&msh, encoding](std::uint8_t x) { encoding == MshEncoding::Binary ? msh.real(x) : msh.size(x); };
    write_element_data(msh, "level", m, [&](std::size_t t) { whole(mesh.levels[t]); });
    write_element_data(msh, "rgb_colour", m, [&](std::size_t t) { whole(mesh.rgb_colours[t]); });
    const std::vector<rgb::TriangleQuality> quality = triangle_qualities(mesh);
    write_element_data(msh, "quality", m, [&](std::size_t t) { msh.real(quality[t].aspect_ratio); });
    write_element_data(msh, "min_angle", m, [&](std::size_t t) { msh.real(quality[t].min_angle); });
    file.commit();
}

}  // namespace rgbio
