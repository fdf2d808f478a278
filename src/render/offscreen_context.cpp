#include "render/offscreen_context.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <dlfcn.h>

// <GL/osmesa.h> needs the GLAPI macros that <glad/gl.h> provides (toolchain.md, pitfall 6).
#include <glad/gl.h>
#include <GL/osmesa.h>

namespace render {
namespace {

OSMesaContext as_osmesa(void* context) { return static_cast<OSMesaContext>(context); }

// libOSMesa, opened on first use rather than linked: linking loads it, and the LLVM it pulls in,
// into every run of the CLI, which cost 70 ms of each command's start (most commands draw nothing).
// It stays loaded for the life of the process, as a linked library would.
struct OsmesaLibrary {
    decltype(&OSMesaCreateContextAttribs) create_context_attribs = nullptr;
    decltype(&OSMesaDestroyContext) destroy_context = nullptr;
    decltype(&OSMesaMakeCurrent) make_current = nullptr;
    decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;
};

const OsmesaLibrary& osmesa() {
    static const OsmesaLibrary library = [] {
        void* handle = nullptr;
        for (const char* name : {"libOSMesa.so.8", "libOSMesa.so"})
            if ((handle = dlopen(name, RTLD_NOW | RTLD_LOCAL)) != nullptr) break;
        if (handle == nullptr) throw std::runtime_error(std::string("cannot load OSMesa (libOSMesa.so.8): ") + dlerror());
        OsmesaLibrary l;
        auto find = [handle](auto& function, const char* name) {
            if ((function = reinterpret_cast<std::remove_reference_t<decltype(function)>>(dlsym(handle, name))) == nullptr)
                throw std::runtime_error(std::string("libOSMesa has no ") + name);
        };
        find(l.create_context_attribs, "OSMesaCreateContextAttribs");
        find(l.destroy_context, "OSMesaDestroyContext");
        find(l.make_current, "OSMesaMakeCurrent");
        find(l.get_proc_address, "OSMesaGetProcAddress");
        return l;
    }();
    return library;
}

}  // namespace

#ifdef __SANITIZE_ADDRESS__
// LeakSanitizer: libOSMesa keeps a few hundred bytes per context that OSMesaDestroyContext does not
// free (Mesa's allocations, made in OSMesaCreateContextAttribs and OSMesaMakeCurrent). The hook lives
// here so that every sanitized program that makes a context carries it; our own leaks still fail.
extern "C" const char* __lsan_default_suppressions() { return "leak:libOSMesa.so\n"; }
// Without this, a program that used the suppression lists it on stderr at exit, after the program's
// own messages, which the CLI tests compare exactly.
extern "C" const char* __lsan_default_options() { return "print_suppressions=0"; }
#endif

OffscreenContext::OffscreenContext(int width, int height) : width_(width), height_(height) {
    if (width <= 0 || height <= 0)
        throw std::runtime_error("offscreen size must be positive, got " + std::to_string(width) + "x" + std::to_string(height));
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    context_ = osmesa().create_context_attribs(attributes, nullptr);
    if (context_ == nullptr) throw std::runtime_error("OSMesa could not create an OpenGL 3.3 core context");
    buffer_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    make_current();
    if (gladLoadGL(reinterpret_cast<GLADloadfunc>(osmesa().get_proc_address)) == 0) {
        osmesa().destroy_context(as_osmesa(context_));
        throw std::runtime_error("could not load OpenGL 3.3 entry points from OSMesa");
    }
}

OffscreenContext::~OffscreenContext() { osmesa().destroy_context(as_osmesa(context_)); }

void OffscreenContext::make_current() {
    if (osmesa().make_current(as_osmesa(context_), buffer_.data(), GL_UNSIGNED_BYTE, width_, height_) == 0)
        throw std::runtime_error("OSMesaMakeCurrent failed");
}

Image OffscreenContext::read_pixels() const {
    glFinish();
    Image image{width_, height_, std::vector<std::uint8_t>(buffer_.size())};
    const std::size_t row = static_cast<std::size_t>(width_) * 4;
    for (int y = 0; y < height_; ++y)
        std::copy_n(buffer_.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(height_ - 1 - y)), row,
                    image.rgba.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y)));
    return image;
}

}  // namespace render
