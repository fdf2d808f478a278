// libFuzzer target: any bytes given to the OBJ loader either load or give an ObjError. What the
// reader accepts must build, adaptive or plain (the loader hands only clean input to the core, and
// uses a saved state only when it reproduces the file). Every mesh that loads must pass the core's
// invariant checks, save, and load back as the same state: base mesh bit for bit, vertex addresses
// and faces.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "io/mesh_file.h"
#include "io/mesh_state_difference.h"
#include "io/obj/obj_error.h"
#include "io/obj_reader.h"
#include "rgb/mesh/invariants.h"
#include "rgb/mesh/state.h"

namespace {

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "obj_loader_fuzz: %s\n", what.c_str());
    std::abort();
}

// A fresh folder under the system's temporary directory for one input's save, removed afterwards
// (libFuzzer leaves without running atexit handlers, so nothing may outlive the input).
class TempFolder {
public:
    TempFolder() {
        std::string pattern = (std::filesystem::temp_directory_path() / "rgbsub_obj_loader_fuzz_XXXXXX").string();
        if (::mkdtemp(pattern.data()) == nullptr) finding("cannot make a temporary folder in " + pattern);
        path_ = pattern;
    }
    ~TempFolder() { std::filesystem::remove_all(path_); }
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

// The mesh the loader builds from `text`, or nothing when it rejects it in a way it may.
std::optional<rgb::Mesh> load(std::string_view text) {
    rgbio::LoadedMesh loaded;
    try {
        loaded = rgbio::read_obj_text(text, "fuzz.obj");
    } catch (const rgbio::ObjError&) {
        return std::nullopt;
    }
    try {
        return rgbio::build_mesh(loaded);
    } catch (const std::exception& error) {
        finding(std::string("the reader accepted what the core rejects: ") + error.what());
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::optional<rgb::Mesh> mesh = load(std::string_view(reinterpret_cast<const char*>(data), size));
    if (!mesh) return 0;
    const rgb::InvariantReport report = rgb::check_invariants(*mesh);
    if (!report.ok()) finding("a loaded mesh breaks an invariant: " + report.violations.front());

    const TempFolder folder;
    const std::string path = (folder.path() / "saved.obj").string();
    rgbio::save_mesh(*mesh, path);  // a SaveError escaping here is a finding too
    const rgb::Mesh reloaded = rgbio::load_mesh(path);
    const std::string difference = rgbio::test::state_difference(rgb::capture_state(*mesh), rgb::capture_state(reloaded));
    if (!difference.empty()) finding("the saved mesh loads back differently: " + difference);
    return 0;
}
