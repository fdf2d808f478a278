// Compiles Debian's ImGui OpenGL3 backend against our glad loader: with
// IMGUI_IMPL_OPENGL_LOADER_CUSTOM the backend expects the GL declarations to be in scope already.
#include <glad/gl.h>

#include "imgui_impl_opengl3.cpp"
