// A cage with detail through save and load (state format version 5, or 6 with levels per base
// face, io/state/detail_state.h): the saved file resumes without the surface it was sampled from;
// every vertex of every level is where the detail puts it, bit for bit, after a reload, a refine of
// the reloaded file and a level 0; an edited v line, a changed detail value or forged levels are
// caught; a malformed section is an error naming its line; other OBJ readers see the displayed mesh;
// a file written before levels per face (format 5) loads and saves again byte for byte.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "io/mesh_file.h"
#include "io/obj/obj_error.h"
#include "io/obj_reader.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/detail_positions.h"
#include "rgb/values/loop_geometry.h"
#include "support/set_level.h"

namespace rgbio {
namespace {

constexpr int kDetailLevel = 2;
// Levels per face of the octahedron: neighbours of equal and of different levels.
const std::vector<std::uint8_t> kMixedLevels{1, 3, 2, 2, 1, 3, 2, 1};

// An octahedron cage; its detail a sphere of radius 1.25 around it (each point pushed out radially
// from the base-space point), values that need 17 digits; every face at kDetailLevel, or at the
// given levels.
std::shared_ptr<const rgb::BaseMesh> cage_with_detail(std::optional<std::vector<std::uint8_t>> face_levels = std::nullopt) {
    const std::vector<glm::dvec3> positions{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const std::vector<rgb::Triangle> triangles{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    const rgb::BaseMesh plain(positions, triangles);
    const std::vector<std::uint8_t> levels = face_levels.value_or(rgb::DetailPositions::uniform_levels(plain, kDetailLevel));
    std::vector<glm::dvec3> values;
    for (const rgb::SurfacePoint& p : rgb::DetailPositions::grid_points(plain, levels)) {
        const glm::dvec3 q = rgb::base_space_position(plain, p);
        values.push_back(1.25 * q / std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z));
    }
    auto detail = std::make_shared<const rgb::DetailPositions>(plain, levels, values, rgb::DetailOrigin{"scan with spaces.obj", 12345, 7});
    return std::make_shared<const rgb::BaseMesh>(positions, triangles, rgb::SharpFeatures{}, detail);
}

// The number of the line of `text` on which `needle` starts.
std::size_t line_of(const std::string& text, const std::string& needle) {
    const std::size_t at = text.find(needle);
    EXPECT_NE(at, std::string::npos) << needle;
    return 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

// A file saved by rgbsub before detail levels per face (state format 5, one level): an octahedron
// refined to level 2, `rgbsub remesh --cage-triangles 8`.
constexpr std::string_view kFormat5Cage = R"(# rgbsub mesh: 6 vertices, 8 triangles; positions: displayed; adaptive state: #rgb lines at the end
v -0.29135374001753944 -0.31556410683608266 -0.04007055629275581
v -0.14525212488686107 0.2990535641930734 -0.2552734983634961
v 0.3232586727652531 -0.24459223821132708 0.11820442804683956
v 0.15410806813938857 0.021957855904716765 0.4128439052049887
v -0.21817724188392942 0.34306529848911554 0.12270431630623724
v 0.3435526944833712 0.21646741724128005 -0.12506551770092936
f 6 3 1
f 5 2 1
f 6 1 2
f 3 6 4
f 4 5 1
f 6 2 5
f 6 5 4
f 1 3 4
# rgbsub adaptive state: the #rgb lines restore the exact RGB mesh; other readers ignore them
#rgb state 5
#rgb positions displayed
#rgb section base-vertices 6
#rgb p -0.8856893738114258 -1.004456740356483 -0.17573225069958404
#rgb p -0.12395868697050128 0.7056649111827531 -0.6202423078490849
#rgb p 0.734487910559312 -0.5104476328055969 0.1458787933142845
#rgb p 0.29783581568990014 0.1620703834494175 0.94970313923006
#rgb p -0.579809389495457 0.7127979165154426 0.3926258275900713
#rgb p 0.8898264628286418 0.4574940713322657 -0.44784260583803764
#rgb section base-faces 8
#rgb t-as-f 0 8
#rgb section addresses 0
#rgb section detail 66
#rgb detail-level 2
#rgb detail-origin 128 0 oct2.obj
#rgb d 0.3435526944833712 0.21646741724128005 -0.12506551770092936 0.4272825092647169 0.06030541033350276 -0.0816106346244489 0.4292901042902009 -0.11798785643348654 0.011574179725084816 0.3511258871511031 -0.21512601423240188 0.10050497917641997 0.3232586727652531 -0.24459223821132708 0.11820442804683956 0.3115634518867881 0.055331219366237125 -0.2877240634300934 0.33843927745194324 -0.17926544105843428 -0.19888112701883964 0.3049445114427798 -0.30840040203260605 -0.02721642304922823
#rgb d 0.27842635510392705 -0.29519158481266866 0.10667037016680848 0.11101170355330015 -0.18936894985767003 -0.3652913320716269 0.10661104798453812 -0.38198522767431764 -0.16472580151741142 0.11805954923656853 -0.4152158229769859 0.05833274225775753 -0.1499328516976742 -0.32639782115823546 -0.22558887799292743 -0.12319866951784914 -0.4296932616206738 -0.00349647006847092 -0.29135374001753944 -0.31556410683608266 -0.04007055629275581 -0.21817724188392942 0.34306529848911554 0.12270431630623724
#rgb d -0.22842808506297174 0.3645927238545863 0.018741609346210806 -0.2003178459468124 0.35258334757281184 -0.13110596895118548 -0.15867376668316263 0.3150027497765089 -0.23261349188190983 -0.14525212488686107 0.2990535641930734 -0.2552734983634961 -0.32080910990245476 0.24054180617037121 0.13120441785434797 -0.36169657818989587 0.2271914484539642 -0.03238216479947334 -0.3022296896334682 0.22449633880534092 -0.1939770965611909 -0.19462045058098038 0.2464752211480602 -0.2796074532709594
#rgb d -0.42741000300969273 0.03734811664551707 0.10420366046964659 -0.42903864258108965 0.021681010016027534 -0.1096691982962238 -0.3031441244022866 0.057974092810817376 -0.2948219541923047 -0.39234583153940933 -0.18303682711724023 0.0270109140297264 -0.34694347916650925 -0.17856717800122635 -0.1893026296802886 0.21860205130242635 0.2788437190374085 -0.2232573546601651 0.10141991410766243 0.1020164050245041 -0.40575041330374173 -0.14451220575042523 -0.09490768859338292 -0.3931561619796672
#rgb d 0.043606933286981994 0.3203386878824459 -0.2848109704740631 -0.10356763810572958 0.17296150428082302 -0.37816354696567156 -0.10044874936368814 0.3121226473104858 -0.2646061030076702 0.32568024821889485 -0.22803818159118894 0.14646939037983242 0.3865226608036208 -0.11212389649936817 0.14624885834742962 0.4242272948032317 0.05057855023411548 0.10006667889950828 0.37175878851770244 0.21629594249720513 0.02187659735810455 0.29879962510617414 -0.1605602992378975 0.24787335027487714
#rgb d 0.3578096451914312 0.007582008446624266 0.24328584738542705 0.341291766618197 0.17808359819682254 0.19661955928339175 0.22619516603962425 -0.058044377941936356 0.35536870896207295 0.24475500976495898 0.09932646036434355 0.3318614656705819 0.15410806813938857 0.021957855904716765 0.4128439052049887 0.05994549480565292 0.10622945112212823 0.4187918939252766 -0.07812313036449367 0.22192234239275072 0.3527267625458143 -0.18329761336412753 0.30983146661926475 0.22547285169867148
#rgb d 0.029621419053113208 -0.0890708799431256 0.4308186610786539 -0.17064171510475445 -0.006125271346219851 0.4062252383884054 -0.2944551929068134 0.11636650679795657 0.27431467869420834 -0.14456328311758307 -0.23399405774328194 0.3206774256979265 -0.3326515000114023 -0.12674195492492696 0.2309306475261342 -0.25668850621347644 -0.30904340061379754 0.12244243634545204 0.2546749794717992 0.33395183351528845 -0.06756238121075875 0.09524008521187716 0.3903861579418963 -0.15209410638270482
#rgb d -0.05958275867231386 0.37087261672300365 -0.2021069404402242 0.09850604823438476 0.43129786261844083 0.016778595367813863 -0.06410243377677574 0.4282471282877572 -0.07287632062139567 -0.09632180842796123 0.41097734963389826 0.09218040690375802 0.24311870512008513 0.32631399031063896 0.11504085913855193 0.03358654903043285 0.3721901047565783 0.21082058975796278 0.1645211059263033 0.24767220671876125 0.2970203653180871 -0.037441788532674006 -0.3803701380027645 0.19685785268027747
#rgb d 0.19868656292381442 -0.32104948118203464 0.20096708089415094 0.10490555398414483 -0.24179313437313363 0.3323004309080926
#rgb end
)";

void expect_on_detail(const rgb::Mesh& mesh, const rgb::BaseMesh& reference) {
    ASSERT_NE(mesh.base().detail(), nullptr);
    for (rgb::VertexId v : mesh.vertices())
        ASSERT_EQ(rgb::displayed_position(mesh, v), reference.detail()->position(reference, mesh.address(v)));
}

TEST(DetailRoundTrip, ASavedCageResumesWithItsDetail) {
    const auto base = cage_with_detail();
    rgb::Mesh mesh(base);
    rgbtest::set_level(mesh, 3, rgb::Sphere{{1, 0, 0}, 0.8});
    const std::string text = format_obj(mesh, {});
    EXPECT_NE(text.find("#rgb state 5\n"), std::string::npos);
    EXPECT_NE(text.find("#rgb detail-origin 12345 7 scan with spaces.obj\n"), std::string::npos);
    const LoadedMesh loaded = read_obj_text(text, "saved.obj");
    ASSERT_TRUE(loaded.adaptive) << (loaded.warnings.empty() ? "" : loaded.warnings.front());
    expect_on_detail(*loaded.adaptive, *base);
    const rgb::DetailOrigin& origin = loaded.adaptive->base().detail()->origin();
    EXPECT_EQ(origin.source, "scan with spaces.obj");
    EXPECT_EQ(origin.source_triangles, 12345u);
    EXPECT_EQ(origin.nearest_points, 7u);
    // The v lines are the displayed mesh (what other readers see): loaded as plain positions, the same.
    std::size_t i = 0;
    for (rgb::VertexId v : loaded.adaptive->vertices()) ASSERT_EQ(loaded.positions[i++], rgb::displayed_position(*loaded.adaptive, v));
    // Refined further and brought back to level 0 from the reloaded file alone.
    rgb::Mesh resumed = *loaded.adaptive;
    rgbtest::set_level(resumed, 4, rgb::Sphere{{0, 0, 1}, 0.5});
    expect_on_detail(resumed, *base);
    rgbtest::set_level(resumed, 0);
    expect_on_detail(resumed, *base);
    EXPECT_EQ(resumed.num_vertices(), 6u);
    // Saved again: the same bytes as the detail saved first, at the same mesh.
    rgb::Mesh again = *loaded.adaptive;
    EXPECT_EQ(format_obj(again, {}), text);
}

TEST(DetailRoundTrip, EditsAreCaught) {
    rgb::Mesh mesh(cage_with_detail());
    rgbtest::set_level(mesh, 2);
    const std::string text = format_obj(mesh, {});
    // A changed detail value no longer gives the v lines: loaded as a plain mesh, with the reason.
    std::string changed = text;
    const std::size_t d = changed.find("#rgb d ");
    ASSERT_NE(d, std::string::npos);
    const std::size_t first_end = changed.find(' ', d + 7);
    changed.replace(d + 7, first_end - (d + 7), "0.123");
    const LoadedMesh plain = read_obj_text(changed, "changed.obj");
    EXPECT_FALSE(plain.adaptive);
    ASSERT_FALSE(plain.warnings.empty());
    EXPECT_NE(plain.warnings.front().find("does not match the file"), std::string::npos) << plain.warnings.front();
    // A section that announces more than it holds names its line.
    std::string short_section = text;
    const std::size_t header = short_section.find("#rgb section detail ");
    ASSERT_NE(header, std::string::npos);
    short_section.insert(header + 20, "1");
    EXPECT_THROW(read_obj_text(short_section, "short.obj"), ObjError);
}

// Levels per face (state format 6): every vertex where the detail puts it after a reload, a refine
// of the reloaded file and a level 0; saved again, the same bytes.
TEST(DetailRoundTrip, LevelsPerFaceResumeExactly) {
    const auto base = cage_with_detail(kMixedLevels);
    rgb::Mesh mesh(base);
    rgbtest::set_level(mesh, 4, rgb::Sphere{{1, 0, 0}, 0.9});
    const std::string text = format_obj(mesh, {});
    EXPECT_NE(text.find("#rgb state 6\n"), std::string::npos);
    EXPECT_NE(text.find("#rgb detail-face-levels 1 3 2 2 1 3 2 1\n"), std::string::npos);
    EXPECT_EQ(text.find("#rgb detail-level "), std::string::npos);
    const LoadedMesh loaded = read_obj_text(text, "saved.obj");
    ASSERT_TRUE(loaded.adaptive) << (loaded.warnings.empty() ? "" : loaded.warnings.front());
    const rgb::DetailPositions& detail = *loaded.adaptive->base().detail();
    EXPECT_TRUE(std::equal(detail.face_levels().begin(), detail.face_levels().end(), kMixedLevels.begin(), kMixedLevels.end()));
    expect_on_detail(*loaded.adaptive, *base);
    rgb::Mesh resumed = *loaded.adaptive;
    rgbtest::set_level(resumed, 5);
    expect_on_detail(resumed, *base);
    rgbtest::set_level(resumed, 0);
    expect_on_detail(resumed, *base);
    rgb::Mesh again = *loaded.adaptive;
    EXPECT_EQ(format_obj(again, {}), text);
}

// Forged levels: out of range, too many or too few are errors naming their line; levels that no
// longer fit the positions drop the state with a warning naming the section's line.
TEST(DetailRoundTrip, TamperedLevelsAreCaught) {
    rgb::Mesh mesh(cage_with_detail(kMixedLevels));
    rgbtest::set_level(mesh, 2);
    const std::string text = format_obj(mesh, {});
    const std::string levels = "#rgb detail-face-levels 1 3 2 2 1 3 2 1\n";
    const std::size_t levels_line = line_of(text, levels);
    auto with_levels = [&](const std::string& record) {
        std::string forged = text;
        forged.replace(forged.find(levels), levels.size(), record);
        return forged;
    };
    auto expect_error_on = [](const std::string& forged, std::size_t line, const std::string& words) {
        try {
            read_obj_text(forged, "forged.obj");
            ADD_FAILURE() << "loaded: " << words;
        } catch (const ObjError& e) {
            EXPECT_EQ(e.line(), line) << e.what();
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
    };
    expect_error_on(with_levels("#rgb detail-face-levels 1 3 2 2 1 13 2 1\n"), levels_line, "out of range");
    expect_error_on(with_levels("#rgb detail-face-levels 1 3 2 2 1 3 2 1 2\n"), levels_line, "more detail levels than the 8 base faces");
    const std::size_t section_line = line_of(text, "#rgb section detail ");
    expect_error_on(with_levels("#rgb detail-face-levels 1 3 2 2 1 3 2\n"), section_line, "7 detail levels for 8 base faces");
    expect_error_on(with_levels("#rgb detail-face-levels 1 3 2 2 1 3 2 1\n#rgb detail-level 2\n"), levels_line + 1, "given twice");
    // In a file of format 5 the record does not exist.
    std::string old_format = text;
    old_format.replace(old_format.find("#rgb state 6"), 12, "#rgb state 5");
    expect_error_on(old_format, levels_line, "unknown record 'detail-face-levels'");
    // A level changed: the positions no longer fit the levels.
    const LoadedMesh plain = read_obj_text(with_levels("#rgb detail-face-levels 1 3 2 2 2 3 2 1\n"), "forged.obj");
    EXPECT_FALSE(plain.adaptive);
    ASSERT_FALSE(plain.warnings.empty());
    EXPECT_NE(plain.warnings.front().find("section on line " + std::to_string(section_line)), std::string::npos) << plain.warnings.front();
    EXPECT_NE(plain.warnings.front().find("needs"), std::string::npos) << plain.warnings.front();
}

// A file saved before levels per face loads as it did: every face at its one level, and saved again
// it is the same file, byte for byte (one level is still written as format 5).
TEST(DetailRoundTrip, AFileOfFormat5LoadsExactly) {
    const LoadedMesh loaded = read_obj_text(kFormat5Cage, "oct_cage.obj");
    ASSERT_TRUE(loaded.adaptive) << (loaded.warnings.empty() ? "" : loaded.warnings.front());
    const rgb::DetailPositions& detail = *loaded.adaptive->base().detail();
    EXPECT_EQ(detail.coarsest_level(), 2);
    EXPECT_EQ(detail.finest_level(), 2);
    EXPECT_EQ(detail.origin().source, "oct2.obj");
    rgb::Mesh again = *loaded.adaptive;
    EXPECT_EQ(format_obj(again, {}), kFormat5Cage);
    // Refined, every vertex of level up to 2 is at its stored point: the uniform grid's values as read.
    rgb::Mesh refined = *loaded.adaptive;
    rgbtest::set_level(refined, 3);
    const rgb::BaseMesh& base = refined.base();
    const std::vector<rgb::SurfacePoint> points = rgb::DetailPositions::grid_points(base, 2);
    const std::vector<glm::dvec3> samples = detail.samples(base);
    ASSERT_EQ(samples.size(), 66u);
    for (std::size_t i = 0; i < points.size(); ++i) ASSERT_EQ(detail.position(base, points[i]), samples[i]);
    const std::string last_record = "#rgb d 0.19868656292381442 -0.32104948118203464 0.20096708089415094 0.10490555398414483";
    EXPECT_EQ(samples[64], glm::dvec3(0.19868656292381442, -0.32104948118203464, 0.20096708089415094));
    EXPECT_NE(std::string(kFormat5Cage).find(last_record), std::string::npos);
}

}  // namespace
}  // namespace rgbio
