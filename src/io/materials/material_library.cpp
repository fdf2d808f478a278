#include "io/materials/material_library.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <istream>
#include <streambuf>
#include <tuple>
#include <utility>
#include <string_view>

#include <tiny_obj_loader.h>

#include "io/files/file_text.h"
#include "io/obj/obj_error.h"
#include "io/obj/printable_text.h"

namespace rgbio {

namespace {

namespace fs = std::filesystem;

std::string trimmed(const std::string& s) {
    const std::size_t b = s.find_first_not_of(" \t\r");
    return b == std::string::npos ? std::string() : s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// An input stream over text in memory, for tinyobjloader, without the copy std::istringstream makes.
class TextStreamBuffer : public std::streambuf {
public:
    explicit TextStreamBuffer(std::string_view text) {
        // Only the get area is set: nothing is ever written through the pointer.
        char* begin = const_cast<char*>(text.data());
        setg(begin, begin, begin + text.size());
    }
};

// What the libraries read so far have cost (kMaxMaterialLibraryBytes, kMaxLibraryMaterials).
struct LibraryCost {
    std::uintmax_t bytes = 0;
    std::size_t materials = 0;
};

// An upper bound of the materials a library defines, counted before tinyobjloader makes them.
std::size_t announced_materials(std::string_view text) {
    std::size_t count = 0;
    for (std::size_t at = text.find("newmtl"); at != std::string_view::npos; at = text.find("newmtl", at + 1)) ++count;
    return count;
}

// Appends the library's materials; the reason when it cannot be read or would take the libraries
// beyond what they may cost.
std::optional<std::string> read_library(const fs::path& path, LibraryCost& cost, std::vector<Material>& materials) {
    auto not_read = [](const std::string& why) { return std::optional<std::string>(why); };
    const auto too_large = [&](std::uintmax_t bytes) {
        return cost.bytes + bytes > kMaxMaterialLibraryBytes
                   ? not_read("it is " + std::to_string(bytes) + " bytes, beyond the " + std::to_string(kMaxMaterialLibraryBytes >> 20) +
                              " MiB that the material libraries of a mesh may take together")
                   : std::nullopt;
    };
    // Its size first, before any of it is read.
    std::error_code error;
    if (const std::uintmax_t bytes = fs::file_size(path, error); !error && too_large(bytes)) return too_large(bytes);
    FileText text;
    try {
        text = read_file_text(path.string());
        text.check_not_shrunk();
    } catch (const ObjError& e) {
        return not_read(e.reason());
    }
    // Again as read: a system file gives no size beforehand (and a file may have grown).
    if (const std::optional<std::string> why = too_large(text.view().size())) return why;
    const std::size_t defined = announced_materials(text.view());
    if (cost.materials + defined > kMaxLibraryMaterials)
        return not_read("it defines " + std::to_string(defined) + " materials, beyond the " + std::to_string(kMaxLibraryMaterials) +
                        " that the material libraries of a mesh may define together");
    cost.bytes += text.view().size();
    cost.materials += defined;
    TextStreamBuffer buffer(text.view());
    std::istream in(&buffer);
    std::map<std::string, int> by_name;
    std::vector<tinyobj::material_t> read;
    std::string warning, parse_error;
    tinyobj::LoadMtl(&by_name, &read, &in, &warning, &parse_error);
    for (const tinyobj::material_t& m : read) {
        Material material;
        material.name = trimmed(m.name);
        material.diffuse = glm::dvec3(m.diffuse[0], m.diffuse[1], m.diffuse[2]);
        if (!m.diffuse_texname.empty()) material.diffuse_texture = resolve_file_reference(m.diffuse_texname, path.parent_path()).string();
        material.library = path.string();
        materials.push_back(std::move(material));
    }
    return std::nullopt;
}

void warn_about_missing_textures(const std::vector<Material>& materials, std::vector<std::string>& warnings) {
    std::size_t missing = 0;
    const Material* first = nullptr;
    for (const Material& m : materials) {
        std::error_code error;
        if (m.diffuse_texture.empty() || fs::is_regular_file(m.diffuse_texture, error)) continue;
        if (missing++ == 0) first = &m;
    }
    if (missing > 0)
        warnings.push_back(std::to_string(missing) + " diffuse textures (map_Kd) are not there, the first " +
                           quoted_file_text(first->diffuse_texture, 200) + " of material " + quoted_file_text(first->name));
}

void warn_about_undefined_materials(const std::vector<Material>& materials, const FaceLabels& face_materials,
                                    std::vector<std::string>& warnings) {
    std::set<std::string, std::less<>> defined;
    for (const Material& m : materials) defined.insert(m.name);
    std::size_t undefined = 0;
    const std::string* first = nullptr;
    for (const std::string& name : face_materials.names)
        if (!defined.contains(name) && undefined++ == 0) first = &name;
    if (undefined > 0)
        warnings.push_back(std::to_string(undefined) + " materials used by faces are defined in no material library (the first " +
                           quoted_file_text(*first) + "); those faces keep the name only");
}

// A name defined again (in its library or a later one) would be counted twice and written twice to
// glTF, while faces get its first definition (material_indices): later ones are dropped.
void drop_redefined_materials(std::vector<Material>& materials, std::vector<std::string>& warnings) {
    std::set<std::string, std::less<>> seen;
    std::size_t again = 0;
    std::string first;
    std::erase_if(materials, [&](const Material& m) {
        if (seen.insert(m.name).second) return false;
        if (again++ == 0) first = quoted_file_text(m.name) + " in " + quoted_file_text(m.library, 200);
        return true;
    });
    if (again > 0)
        warnings.push_back(std::to_string(again) + " material definitions repeat a name defined before, the first " + first +
                           "; each name keeps its first definition");
}

}  // namespace

fs::path resolve_file_reference(const std::string& written, const fs::path& folder) {
    std::string path = written;
    std::replace(path.begin(), path.end(), '\\', '/');
    const fs::path p(path);
    return (p.is_absolute() ? p : folder / p).lexically_normal();
}

std::vector<Material> read_material_libraries(const std::vector<std::string>& libraries, const fs::path& obj_folder,
                                              const FaceLabels& face_materials, std::vector<std::string>& warnings) {
    std::vector<Material> materials;
    LibraryCost cost;
    // One warning for every library not read (a file may name 100,000 missing ones): the count, the
    // first and why.
    std::size_t unread = 0;
    std::string first_unread, first_why;
    std::set<fs::path> seen;  // canonical paths: a library named again (in any spelling) is read once
    for (const std::string& library : libraries) {
        const fs::path path = resolve_file_reference(library, obj_folder);
        std::error_code error;
        const fs::path canonical = fs::weakly_canonical(path, error);
        if (!seen.insert(error ? path : canonical).second) continue;
        if (const std::optional<std::string> why = read_library(path, cost, materials); why && unread++ == 0)
            std::tie(first_unread, first_why) = std::pair(quoted_file_text(path.string(), 200), *why);
    }
    if (unread == 1)
        warnings.push_back("material library " + first_unread + " was not read (" + first_why + "); faces keep their material names");
    if (unread > 1)
        warnings.push_back(std::to_string(unread) + " material libraries were not read, the first " + first_unread + " (" + first_why +
                           "); faces keep their material names");
    drop_redefined_materials(materials, warnings);
    warn_about_missing_textures(materials, warnings);
    // An unread library was reported already; without any library, names are all a file has.
    if (unread == 0 && !libraries.empty()) warn_about_undefined_materials(materials, face_materials, warnings);
    return materials;
}

}  // namespace rgbio
