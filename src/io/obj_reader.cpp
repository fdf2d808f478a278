#include "io/obj_reader.h"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/material_library.h"
#include "io/mesh_validation.h"
#include "io/obj_error.h"
#include "io/obj_parser.h"
#include "io/state_format.h"
#include "io/truncation_check.h"

namespace rgbio {

std::string read_text_file(const std::string& path) {
    auto unreadable = [&](const std::string& why) { return ObjError(ObjProblem::Unreadable, path, 0, "cannot read the file: " + why); };
    // O_NONBLOCK: opening a FIFO must not wait for a writer; the check below refuses it anyway.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) throw unreadable(std::strerror(errno));
    struct stat info {};
    if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        ::close(fd);
        throw unreadable(S_ISDIR(info.st_mode) ? "it is a directory" : "it is not a regular file");
    }
    std::string text;
    text.resize(static_cast<std::size_t>(info.st_size));
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t got = ::read(fd, text.data() + done, text.size() - done);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) {
            const int error = got < 0 ? errno : 0;
            ::close(fd);
            throw unreadable(error ? std::strerror(error) : "the file shrank while reading");
        }
        done += static_cast<std::size_t>(got);
    }
    ::close(fd);
    return text;
}

namespace {

// The state's live vertices, in slot order, must be the v lines and its live faces the f lines.
bool state_matches_body(const rgb::MeshState& state, const ObjRecords& records) {
    std::vector<std::uint32_t> obj_index(state.vertices.size(), UINT32_MAX);
    std::uint32_t next = 0;
    for (std::size_t v = 0; v < state.vertices.size(); ++v)
        if (state.vertices[v].alive) obj_index[v] = next++;
    if (next != records.positions.size()) return false;
    std::size_t polygon = 0;
    for (const rgb::FaceState& f : state.faces) {
        if (!f.alive) continue;
        if (polygon == records.polygons.size() || records.polygons[polygon].vertices.size() != 3) return false;
        for (int i = 0; i < 3; ++i)
            if (f.v[i] >= obj_index.size() || obj_index[f.v[i]] != records.polygons[polygon].vertices[i]) return false;
        ++polygon;
    }
    return polygon == records.polygons.size();
}

}  // namespace

namespace {

LoadedMesh read_records(const ObjRecords& records, const std::string& name, const ReadOptions& options) {
    std::vector<std::string> warnings;
    if (!records.state.empty()) {
        rgb::MeshState state = parse_state(records.state, name);
        if (state_matches_body(state, records)) {
            LoadedMesh loaded = saved_mesh_content(records);
            loaded.state = std::move(state);
            return loaded;
        }
        warnings.push_back("the rgbsub state (#rgb lines) does not match the faces, so the file was probably edited by "
                           "another program; it is loaded as a plain mesh");
    }
    LoadedMesh loaded = validate_mesh(records, name, options);
    loaded.warnings.insert(loaded.warnings.begin(), warnings.begin(), warnings.end());
    return loaded;
}

}  // namespace

LoadedMesh read_obj_text(std::string_view text, const std::string& name, const ReadOptions& options) {
    const std::optional<SavedFileHeader> header = read_saved_file_header(text);
    if (!header) return read_records(parse_obj(text, name), name, options);
    try {
        const ObjRecords records = parse_obj(text, name);
        check_saved_file_complete(*header, records, text, name);
        return read_records(records, name, options);
    } catch (const ObjError& error) {
        throw truncation_or(error, *header, text, name);
    }
}

LoadedMesh read_obj_file(const std::string& path, const ReadOptions& options) {
    LoadedMesh loaded = read_obj_text(read_text_file(path), path, options);
    loaded.materials = read_material_libraries(loaded.material_libraries, std::filesystem::path(path).parent_path(),
                                               loaded.face_materials, loaded.warnings);
    return loaded;
}

}  // namespace rgbio
