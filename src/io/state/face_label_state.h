#pragma once
// The base faces' labels (usemtl, g, o, s) as an optional section of the saved adaptive state
// (state_format.h), written only for a mesh that has labels:
//
//   #rgb section face-labels N         N: the number of base faces; then, in any order,
//   #rgb material NAME                 the name tables, one line per name in index order (NAME: the
//   #rgb group NAME                    rest of the line, as usemtl, g or o wrote it, trimmed)
//   #rgb object NAME
//   #rgb l M G O S [M G O S ...]       per base face in base order, up to 8 faces a line: M, G, O are
//                                      1-based indices into the tables (0: none), S the smoothing
//                                      group (0: off)
//
// A reader without this section refuses it by name ("unknown section 'face-labels'"), so a file
// with labels is never resumed without them. The body of a saved file writes the same labels on its
// faces (labelled_faces.h); loading checks that the two agree (an edit in another program wins).
// A state without the section takes its base faces' labels from the body, if its faces agree.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "io/obj/loaded_mesh.h"
#include "io/obj/obj_parser.h"
#include "rgb/mesh/mesh.h"

namespace rgbio {

// Appends the section; nothing when `labels` is empty.
void append_face_label_section(const BaseFaceLabels& labels, std::size_t base_faces, std::string& out);

// Collects the section's lines while the state is parsed (parse_state hands it every line).
class FaceLabelSectionReader {
public:
    explicit FaceLabelSectionReader(const std::string& file) : file_(file) {}
    // Whether the line is this section's header or one of its records (then it is read here). Throws
    // ObjError(BadState) naming the line for a malformed one.
    bool take(const ObjStateLine& line);
    // The labels, checked against the number of base faces; empty without the section. `last` is
    // the line named for problems of the whole section.
    BaseFaceLabels finish(std::size_t base_faces, const ObjStateLine& last) const;

private:
    const std::string& file_;
    bool seen_ = false, inside_ = false;
    std::size_t announced_ = 0;
    std::vector<std::string> names_[3];            // material, group, object
    std::vector<std::uint32_t> indices_[3];        // per base face, 1-based (0: none)
    std::vector<std::uint32_t> smoothing_groups_;  // per base face
};

// The base faces' labels as the file's faces give them (records.polygons: face slot i is f line i),
// each from the first face inside it: for a state saved without a face-labels section, whose body
// another program labelled. label_mismatch then tells whether every face agrees with them.
BaseFaceLabels body_labels(const rgb::Mesh& mesh, const ObjRecords& records);

// Why the labels the file's faces carry (records.polygons: face slot i is f line i) differ from those
// their base faces have in the state, or nothing when every face agrees, by name.
std::optional<std::string> label_mismatch(const rgb::Mesh& mesh, const BaseFaceLabels& labels, const ObjRecords& records);

}  // namespace rgbio
