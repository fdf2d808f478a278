// libFuzzer target: any bytes given to the OBJ loader either load or give an ObjError, and what
// loads as a plain mesh is accepted by rgb::Mesh (the loader hands only clean input to the core).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/mesh_file.h"
#include "io/obj_error.h"
#include "io/obj_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    rgbio::LoadedMesh loaded;
    try {
        loaded = rgbio::read_obj_text(text, "fuzz.obj");
    } catch (const rgbio::ObjError&) {
        return 0;
    }
    // Exceptions escaping here are findings: validation let something through.
    const rgb::Mesh mesh = rgbio::build_mesh(loaded);
    return 0;
}
