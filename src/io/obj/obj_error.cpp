#include "io/obj/obj_error.h"

namespace rgbio {

namespace {

std::string locate(const std::string& file, std::size_t line) {
    return line == 0 ? file : file + ":" + std::to_string(line);
}

}  // namespace

const char* problem_name(ObjProblem p) {
    switch (p) {
        case ObjProblem::Unreadable: return "unreadable file";
        case ObjProblem::Empty: return "empty file";
        case ObjProblem::Binary: return "binary content";
        case ObjProblem::Utf16: return "UTF-16 text";
        case ObjProblem::Syntax: return "syntax error";
        case ObjProblem::FaceIndexZero: return "face index 0";
        case ObjProblem::FaceIndexOutOfRange: return "face index out of range";
        case ObjProblem::NonFiniteCoordinate: return "non-finite coordinate";
        case ObjProblem::AbsurdCoordinate: return "absurd coordinate";
        case ObjProblem::NoFaces: return "no faces";
        case ObjProblem::DegenerateFace: return "degenerate face";
        case ObjProblem::DuplicateFace: return "duplicate face";
        case ObjProblem::NonManifoldEdge: return "non-manifold edge";
        case ObjProblem::NonManifoldVertex: return "non-manifold vertex";
        case ObjProblem::NonOrientable: return "non-orientable surface";
        case ObjProblem::BadState: return "bad rgbsub state";
        case ObjProblem::ComplexPolygon: return "polygon too complex";
        case ObjProblem::Truncated: return "truncated file";
        case ObjProblem::BadTag: return "bad tag line";
        case ObjProblem::OutOfScale: return "mesh out of scale";
        case ObjProblem::Malformed: return "malformed file";
    }
    return "unknown problem";
}

ObjError::ObjError(ObjProblem problem, const std::string& file, std::size_t line, const std::string& reason)
    : std::runtime_error(locate(file, line) + ": " + reason), problem_(problem), file_(file), line_(line),
      reason_(reason) {}

}  // namespace rgbio
