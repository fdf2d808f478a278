#pragma once
// Errors of the io layer. Every message names the file, the OBJ line when known, and the reason,
// in the form `FILE:LINE: reason` so that editors and terminals can jump to it.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace rgbio {

// What is wrong with an input file; tests and the CLI's exit codes key off this, users read what().
enum class ObjProblem {
    Unreadable,           // missing, a directory, no permission, read error
    Empty,                // zero bytes or only whitespace
    Binary,               // NUL bytes that are not UTF-16 text
    Utf16,                // UTF-16 text (BOM or interleaved NULs)
    Syntax,               // a v/f line that cannot be parsed (not a number, too few values)
    FaceIndexZero,        // OBJ indices start at 1
    FaceIndexOutOfRange,  // refers to a vertex that does not exist (yet)
    NonFiniteCoordinate,  // nan or inf
    AbsurdCoordinate,     // magnitude above kMaxCoordinate
    NoFaces,              // nothing to build a surface from
    DegenerateFace,       // a face uses one vertex twice
    DuplicateFace,        // two faces over the same vertices
    NonManifoldEdge,      // an edge with more than two faces (only when reading strictly)
    NonManifoldVertex,    // a bow-tie: the faces around a vertex form several fans (strictly)
    NonOrientable,        // no choice of face flips makes neighbours agree (Moebius strip)
    BadState,             // the rgbsub state comments are malformed or not a valid RGB mesh
    ComplexPolygon,       // a polygon too tangled to triangulate within the work budget
    Truncated,            // a file rgbsub wrote (its header says so) that was cut short
    BadTag,               // an OpenSubdiv tag line (t crease/corner/...) is malformed or names no edge/vertex
    OutOfScale,           // valid, but too small or too large for the numbers rgbsub works or draws in (io/scale_check.h)
    Malformed,            // a file of another format (glTF, PLY, Assimp's) that its reader refuses; the reason says why
};

const char* problem_name(ObjProblem p);

class ObjError : public std::runtime_error {
public:
    // line 0 means "not tied to one line".
    ObjError(ObjProblem problem, const std::string& file, std::size_t line, const std::string& reason);
    ObjProblem problem() const { return problem_; }
    const std::string& file() const { return file_; }
    std::size_t line() const { return line_; }
    const std::string& reason() const { return reason_; }

private:
    ObjProblem problem_;
    std::string file_;
    std::size_t line_;
    std::string reason_;
};

// Writing failed (no space, read-only folder, parent is not a folder...). The target file, if it
// existed, is untouched.
class SaveError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace rgbio
