// Parsing OBJ text in blocks on several threads gives what parsing it in one piece gives: the same
// records field by field, and for a bad line the same error (kind, line and message), wherever the
// blocks are cut. The text mixes everything whose meaning depends on earlier lines: indices (also
// negative ones), labels set before a block and used in it, colours starting part way, line ends of
// all three kinds, skipped statements, state and tag lines (every kind of line the parser keeps).
#include <random>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "io/obj/obj_blocks.h"
#include "io/obj/obj_error.h"

namespace rgbio {
namespace {

std::string mixed_obj(unsigned seed, std::size_t lines) {
    std::mt19937 random(seed);
    auto pick = [&](int n) { return static_cast<int>(random() % static_cast<unsigned>(n)); };
    const char* ends[] = {"\n", "\r\n", "\r"};
    std::string text;
    int positions = 0, texcoords = 0;
    bool colours = false;
    for (std::size_t i = 0; i < lines; ++i) {
        std::string line;
        const int kind = positions < 3 ? 0 : pick(16);
        if (kind <= 4) {
            line = "v " + std::to_string(pick(100) * 0.25) + " " + std::to_string(pick(7)) + " -" + std::to_string(pick(9)) + "e-1";
            colours = colours || pick(20) == 0;
            if (colours && pick(3) > 0) line += " 0.5 0.25 1";
            ++positions;
        } else if (kind == 5) {
            line = "vt " + std::to_string(pick(4) * 0.25) + (pick(2) ? " 0.5" : "") + (pick(4) == 0 ? " 0.5" : "");
            ++texcoords;
        } else if (kind <= 9) {
            line = "f";
            const int corners = 3 + pick(3) / 2;
            for (int c = 0; c < corners; ++c) {
                const int v = 1 + pick(positions);
                line += ' ' + std::to_string(pick(4) == 0 ? v - positions - 1 : v);
                const bool with_texcoord = texcoords > 0 && kind >= 8;
                if (with_texcoord) line += '/' + std::to_string(1 + pick(texcoords));
                if (kind == 9) line += with_texcoord ? "/1" : "//1";
            }
        } else if (kind == 10) {
            const char* labels[] = {"usemtl red", "usemtl blue", "usemtl", "g part one", "g", "o body", "s 2", "s off", "s 1"};
            line = labels[pick(9)];
        } else if (kind == 11) {
            const char* skipped[] = {"vn 0 0 1", "l 1 2", "p 1", "curv 0 1 1 2", "foo bar", "mtllib a.mtl b.mtl"};
            line = skipped[pick(6)];
        } else if (kind == 12) {
            const std::string comments[] = {"# a comment", "#rgb not a state " + std::to_string(i),
                                            "t crease 2/1/0 0 " + std::to_string(i) + " 10"};
            line = comments[pick(3)];
        } else {
            line = pick(2) ? "" : "  \t";
        }
        text += line + ends[pick(8) == 0 ? 1 + pick(2) : 0];
    }
    return text;
}

void expect_same_skipped(const SkippedLines& a, const SkippedLines& b, const char* what) {
    EXPECT_EQ(a.count, b.count) << what;
    EXPECT_EQ(a.first_line, b.first_line) << what;
    EXPECT_EQ(a.first_keyword, b.first_keyword) << what;
}

void expect_same_records(const ObjRecords& a, const ObjRecords& b) {
    EXPECT_EQ(std::tie(a.positions, a.position_lines, a.colours, a.has_colour, a.texcoords),
              std::tie(b.positions, b.position_lines, b.colours, b.has_colour, b.texcoords));
    expect_same_skipped(a.texcoord_w, b.texcoord_w, "vt w");
    ASSERT_EQ(a.polygons.size(), b.polygons.size());
    for (std::size_t i = 0; i < a.polygons.size(); ++i) {
        const ObjPolygon p = a.polygons[i], q = b.polygons[i];
        EXPECT_TRUE(std::equal(p.vertices.begin(), p.vertices.end(), q.vertices.begin(), q.vertices.end())) << "face " << i;
        EXPECT_TRUE(std::equal(p.texcoords.begin(), p.texcoords.end(), q.texcoords.begin(), q.texcoords.end())) << "face " << i;
        EXPECT_EQ(p.line, q.line);
        EXPECT_EQ(p.material, q.material) << "face " << i;
        EXPECT_EQ(p.group, q.group) << "face " << i;
        EXPECT_EQ(p.object, q.object) << "face " << i;
        EXPECT_EQ(p.smoothing_group, q.smoothing_group) << "face " << i;
    }
    EXPECT_EQ(std::tie(a.material_names, a.group_names, a.object_names, a.material_libraries, a.line_elements, a.point_elements),
              std::tie(b.material_names, b.group_names, b.object_names, b.material_libraries, b.line_elements, b.point_elements));
    expect_same_skipped(a.normals, b.normals, "vn");
    expect_same_skipped(a.unsupported, b.unsupported, "unsupported");
    expect_same_skipped(a.unknown, b.unknown, "unknown");
    for (auto lines : {&ObjRecords::state, &ObjRecords::tags}) {
        ASSERT_EQ((a.*lines).size(), (b.*lines).size());
        for (std::size_t i = 0; i < (a.*lines).size(); ++i) {
            EXPECT_EQ((a.*lines)[i].text, (b.*lines)[i].text);
            EXPECT_EQ((a.*lines)[i].line, (b.*lines)[i].line);
        }
    }
    EXPECT_EQ(std::tie(a.v_line_starts, a.f_line_starts, a.last_line), std::tie(b.v_line_starts, b.f_line_starts, b.last_line));
}

ObjError error_of(const std::string& text, std::size_t blocks) {
    try {
        parse_obj_in_blocks(text, "blocks.obj", blocks);
    } catch (const ObjError& e) {
        return e;
    }
    ADD_FAILURE() << "no error in " << blocks << " blocks";
    return ObjError(ObjProblem::Unreadable, "", 0, "none");
}

TEST(ObjBlocks, EveryCutGivesTheRecordsOfOnePiece) {
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const std::string text = mixed_obj(seed, 400);
        const ObjRecords whole = parse_obj_in_blocks(text, "blocks.obj", 1);
        ASSERT_GT(whole.polygons.size(), 50u);
        for (std::size_t blocks = 2; blocks <= 7; ++blocks) {
            SCOPED_TRACE("seed " + std::to_string(seed) + ", " + std::to_string(blocks) + " blocks");
            expect_same_records(parse_obj_in_blocks(text, "blocks.obj", blocks), whole);
        }
    }
}

// A file large enough for parse_obj to cut it into blocks on its own (4 MiB a block, as many as
// the cores), and into more blocks than that.
TEST(ObjBlocks, ALargeFileGivesTheRecordsOfOnePiece) {
    const std::string text = mixed_obj(21, 600000);
    ASSERT_GE(text.size(), std::size_t(8) << 20);
    const ObjRecords whole = parse_obj_in_blocks(text, "large.obj", 1);
    ASSERT_FALSE(whole.tags.empty());
    expect_same_records(parse_obj(text, "large.obj"), whole);
    expect_same_records(parse_obj_in_blocks(text, "large.obj", 16), whole);
}

TEST(ObjBlocks, LabelsSetBeforeABlockReachItsFaces) {
    // One label line, at the top; every face after it carries it, in every block.
    std::string text = "usemtl only\ng shell\ns 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (int i = 0; i < 300; ++i) text += "f 1 2 3\n";
    for (std::size_t blocks = 1; blocks <= 5; ++blocks) {
        const ObjRecords records = parse_obj_in_blocks(text, "labels.obj", blocks);
        ASSERT_EQ(records.polygons.size(), 300u);
        EXPECT_EQ(records.material_names, std::vector<std::string>{"only"});
        EXPECT_EQ(records.group_names, std::vector<std::string>{"shell"});
        for (std::size_t i = 0; i < 300; ++i) {
            EXPECT_EQ(records.polygons[i].material, 0u);
            EXPECT_EQ(records.polygons[i].group, 0u);
            EXPECT_EQ(records.polygons[i].smoothing_group, 3u);
            EXPECT_EQ(records.polygons[i].line, 7 + i);
        }
    }
}

TEST(ObjBlocks, AnErrorLateInTheTextIsReportedAsInOnePiece) {
    const std::string good = mixed_obj(7, 400);
    for (const std::string bad : {"f 1 2 100000", "v 1 2 x", "f 1 2", "vt", "s sometimes", "f 0 1 2", "f 1/2/3/4 1 2"}) {
        // Unknown keywords before the bad line feed the hint of an index error.
        const std::string text = good + "V 1 2 3\n" + bad + "\n" + mixed_obj(8, 50);
        const ObjError whole = error_of(text, 1);
        for (std::size_t blocks = 2; blocks <= 5; ++blocks) {
            const ObjError e = error_of(text, blocks);
            EXPECT_EQ(e.problem(), whole.problem()) << bad;
            EXPECT_EQ(e.line(), whole.line()) << bad;
            EXPECT_EQ(std::string(e.what()), std::string(whole.what())) << bad;
        }
    }
}

}  // namespace
}  // namespace rgbio
