// libFuzzer target: any bytes given to the OBJ loader either load or give an ObjError. What the
// reader accepts must build, adaptive or plain (the loader hands only clean input to the core, and
// uses a saved state only when it reproduces the file). Every mesh that loads must pass the core's
// invariant checks, save, and load back as the same state: base mesh bit for bit, vertex addresses
// and faces.
//
// Each input is also read from a file, which takes the paths text in memory does not (the text
// released once a saved state is parsed, before the rest of the file is used); one in two inputs
// with state or tag lines and one in eight others are also read padded with comment lines between
// their lines to above 8 MiB, so that they are mapped and parsed in blocks cut inside them. Either
// must give what the text in memory gives: the same state (tags included), or a rejection. The
// seeds (seeds/, made with the rgbsub binary) include saved files with tags, texture coordinates,
// colours and labels.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
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

// The mesh the loader builds from what `read` gives, or nothing when it rejects it in a way it may.
template <class Read>
std::optional<rgb::Mesh> load(const Read& read) {
    rgbio::LoadedMesh loaded;
    try {
        loaded = read();
    } catch (const rgbio::ObjError&) {
        return std::nullopt;
    }
    try {
        return rgbio::build_mesh(loaded);
    } catch (const std::exception& error) {
        finding(std::string("the reader accepted what the core rejects: ") + error.what());
    }
}

// `text` (with at least one line feed) with comment lines after each of its line feeds, to above
// 8 MiB in all: the same content on the same kinds of lines, its first line still first, in a file
// that is mapped and parsed in blocks.
std::string padded(std::string_view text, std::size_t line_feeds) {
    constexpr std::size_t kPaddedBytes = std::size_t(9) << 20;
    const std::string comment = "#" + std::string(1022, '-') + "\n";
    const std::size_t comments_per_line = kPaddedBytes / comment.size() / line_feeds + 1;
    std::string out;
    out.reserve(kPaddedBytes + text.size() + comment.size() * comments_per_line);
    for (const char c : text) {
        out += c;
        if (c == '\n')
            for (std::size_t i = 0; i < comments_per_line; ++i) out += comment;
    }
    return out;
}

void write_file(const std::string& path, std::string_view text) {
    std::ofstream out(path, std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    if (!out.flush()) finding("cannot write " + path);
}

// `text` read from a file must give what it gives in memory (`expected`).
void expect_same_from_file(const std::optional<rgb::Mesh>& expected, std::string_view text, const std::string& path,
                           const char* how) {
    write_file(path, text);
    const std::optional<rgb::Mesh> from_file = load([&] { return rgbio::read_obj_file(path); });
    if (expected.has_value() != from_file.has_value())
        finding(std::string(how) + " is " + (from_file ? "accepted" : "rejected") + ", in memory it is not");
    if (!expected) return;
    const std::string difference = rgbio::test::state_difference(rgb::capture_state(*expected), rgb::capture_state(*from_file));
    if (!difference.empty()) finding(std::string(how) + " loads differently from memory: " + difference);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const std::optional<rgb::Mesh> mesh = load([&] { return rgbio::read_obj_text(text, "fuzz.obj"); });
    const TempFolder folder;
    expect_same_from_file(mesh, text, (folder.path() / "input.obj").string(), "the file");
    // Padded: one in two inputs with state or tag lines (the lines a large saved file lost in later
    // blocks or read after its text was released, issue 30), one in eight others; chosen by their
    // bytes, so that an input is always chosen alike. A padded input takes about 20 times as long.
    const auto line_feeds = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
    const bool state_or_tags = text.find("#rgb ") != std::string_view::npos || text.find("\nt ") != std::string_view::npos;
    if (line_feeds > 0 && std::hash<std::string_view>{}(text) % (state_or_tags ? 2 : 8) == 0)
        expect_same_from_file(mesh, padded(text, line_feeds), (folder.path() / "padded.obj").string(), "the padded file");
    if (!mesh) return 0;
    const rgb::InvariantReport report = rgb::check_invariants(*mesh);
    if (!report.ok()) finding("a loaded mesh breaks an invariant: " + report.violations.front());

    const std::string path = (folder.path() / "saved.obj").string();
    rgbio::save_mesh(*mesh, path);  // a SaveError escaping here is a finding too
    const rgb::Mesh reloaded = rgbio::load_mesh(path);
    const std::string difference = rgbio::test::state_difference(rgb::capture_state(*mesh), rgb::capture_state(reloaded));
    if (!difference.empty()) finding("the saved mesh loads back differently: " + difference);
    return 0;
}
