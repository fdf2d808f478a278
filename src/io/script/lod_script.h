#pragma once
// Folder io/script (LOD scripts, criteria edits, the triangle limit): includes io/obj, io/files and
// the core.
// The script language of level-of-detail edits, shared by `rgbsub apply` and the editor's stroke
// recorder: one edit per line, every coordinate in base space (spec §3.5), so a script means the same
// on any storage of the mesh and replays to the identical mesh.
//
//   level N [sphere X Y Z R]     set the level to N in the ball (everywhere without one)
//   refine N [sphere X Y Z R]    at least level N there
//   coarsen N [sphere X Y Z R]   at most level N there
//   budget TRIANGLES             the LOD driver: refine the longest edges up to the budget, or trim
//   max-edge L [sphere X Y Z R]  no green edge (an edge of a uniform level) longer than L (world
//                                units, or L% of the bounding-box diagonal) in the uniform mesh of
//                                its level, as coarse as that allows; red and blue diagonals can be
//                                longer
//   tolerance E [sphere X Y Z R] the displayed surface within E (or E%) of the Loop limit surface at
//                                its samples (between them up to 3% above E), in the smallest mesh
//                                in which no unsplit edge could push the error over E
//                                (both in a ball: set by default; a trailing `refine` only adds the
//                                detail, `coarsen` only removes it: rgb/lod/lod_criteria.h)
//   brush refine|coarsen|set LEVEL RADIUS [FALLOFF]
//                                the brush that the following dabs use (FALLOFF: fraction 0..1)
//   dab X Y Z [VX VY VZ] [mirror AXES]
//                                one dab at X Y Z; with a view direction, only faces facing it and
//                                connected to the dab's face through the surface are painted; with
//                                mirror (AXES: x, y, z or several, as xz), the dab and its mirror
//                                images across those planes of base space (x = 0, ...) as one request
// Blank lines and lines starting with # are skipped.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/vec3.hpp>

#include "io/script/detail_edit.h"
#include "rgb/lod/dab.h"
#include "rgb/lod/requests.h"

namespace rgb {
class Mesh;
}

namespace rgbio {

struct BudgetEdit {
    std::size_t triangles = 0;
};
struct BrushEdit {
    rgb::BrushMode mode = rgb::BrushMode::Refine;
    int level = 0;
    double radius = 0.0;
    double falloff = 0.0;
};
// Mirror planes of base space (the mesh's own frame), a bit each: across x = 0, y = 0, z = 0.
inline constexpr std::uint8_t kMirrorX = 1, kMirrorY = 2, kMirrorZ = 4;

struct DabEdit {
    glm::dvec3 centre{0.0};
    std::optional<glm::dvec3> view;
    std::uint8_t mirror = 0;  // kMirrorX | kMirrorY | kMirrorZ
};

// A dab and its mirror images across the planes in `mirror` (symmetric painting): the dab first,
// then the image across each set of those planes in the order of its bits (x, y, xy, z, xz, yz, xyz),
// centre and view direction reflected. Applied in this order they are one request: `dab ... mirror`
// lines and the editor's symmetric brush give the same mesh.
std::vector<rgb::Dab> with_mirror_images(const rgb::Dab& dab, std::uint8_t mirror);

struct ScriptLine {
    std::size_t line = 0;
    std::string text;  // as written, for --timings
    std::variant<rgb::LevelRequest, BudgetEdit, BrushEdit, DabEdit, DetailEdit> edit;
};

// Throws ObjError "SCRIPT:LINE: reason" (Unreadable when the file cannot be read, Syntax for a bad
// line, including a dab before any brush line) so that the exit codes match those of mesh files.
std::vector<ScriptLine> read_lod_script(const std::string& file);
std::vector<ScriptLine> parse_lod_script(const std::string& text, const std::string& file);

// Runs scripts line by line, remembering the brush.
class ScriptRunner {
public:
    // Detail edits (max-edge, tolerance) that would need more triangles throw TooLarge.
    explicit ScriptRunner(std::size_t max_triangles = 1'000'000'000) : max_triangles_(max_triangles) {}
    rgb::RequestStats run(rgb::Mesh& mesh, const ScriptLine& line);
    // The dab a dab line makes with the current brush.
    rgb::Dab dab(const DabEdit& edit) const;
    // After a tolerance line over the whole surface: the error the result reached.
    std::optional<double> reached_error() const { return reached_error_; }

private:
    BrushEdit brush_;
    std::size_t max_triangles_;
    std::optional<double> reached_error_;
};

// The lines the editor's stroke recorder writes; parse_lod_script reads them back exactly.
std::string format_brush_line(const BrushEdit& brush);
std::string format_dab_line(const DabEdit& dab);
// A max-edge or tolerance line (the editor's detail-size dabs), numbers in shortest round-trip form.
std::string format_detail_line(const DetailEdit& edit);

}  // namespace rgbio
