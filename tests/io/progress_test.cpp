// Progress of reading and writing a file (rgb/support/progress.h): what a listener hears only grows, moves
// many times on the way through a file of a hundred thousand triangles, and ends at exactly 1, for a
// saved file read back (parse, then restore) and for the save itself.
#include <algorithm>
#include <filesystem>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "io/mesh_file.h"
#include "io/obj/obj_blocks.h"
#include "io/obj/obj_error.h"
#include "io/obj_reader.h"
#include "obj_test_support.h"
#include "rgb/lod/refine.h"
#include "rgb/support/progress.h"
#include "scratch_folder.h"
#include "support/same_mesh.h"

namespace rgbio {
namespace {

// What a listener heard.
struct Heard {
    std::vector<double> values;
    rgb::Progress progress{[this](double f) { values.push_back(f); }};
};

// Every value larger than the one before, the last exactly 1.
void expect_grows_to_one(const std::vector<double>& values) {
    ASSERT_FALSE(values.empty());
    for (std::size_t i = 1; i < values.size(); ++i) EXPECT_LT(values[i - 1], values[i]) << "report " << i;
    EXPECT_GT(values.front(), 0.0);
    EXPECT_EQ(values.back(), 1.0);
}

TEST(Progress, OnlyGrowsAndTellsTheListenerEachThousandthOnce) {
    Heard heard;
    heard.progress.reach(0.25);
    heard.progress.reach(0.1);      // behind: ignored
    heard.progress.reach(0.2504);   // the same thousandth as 0.25: not told
    heard.progress.reach(0.2511);   // the next one: told
    heard.progress.reach(7.0);      // beyond the end: 1
    EXPECT_EQ(heard.progress.fraction(), 1.0);
    EXPECT_EQ(heard.values, (std::vector<double>{0.25, 0.2511, 1.0}));
}

TEST(Progress, SpansAndCountersMapTheirPartOntoTheWhole) {
    rgb::Progress progress;
    const rgb::ProgressSpan whole(&progress);
    const rgb::ProgressSpan second_half = whole.part(0.5, 1.0);
    second_half.part(0.5, 1.0).reach(0.5);  // 0.5 + 0.5 * (0.5 + 0.5 * 0.5)
    EXPECT_EQ(progress.fraction(), 0.875);
    rgb::ProgressCounter counter(whole.part(0.0, 0.5), 8);
    counter.add(4);  // 0.25: behind
    EXPECT_EQ(progress.fraction(), 0.875);
    rgb::ProgressCounter late(second_half, 4);
    late.add(3);  // 0.5 + 0.5 * 3/4
    EXPECT_EQ(progress.fraction(), 0.875);
    late.add(3);  // more than counted: the span's end, no further
    EXPECT_EQ(progress.fraction(), 1.0);
}

// Threads racing to report: the listener still hears a growing sequence ending at the largest value.
TEST(Progress, ReportsFromManyThreadsReachTheListenerInOrder) {
    Heard heard;
    rgb::ProgressCounter counter(rgb::ProgressSpan(&heard.progress), 4 * 10000);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&] {
            for (int i = 0; i < 10000; ++i) counter.add(1);
        });
    for (std::thread& t : threads) t.join();
    expect_grows_to_one(heard.values);
    EXPECT_GE(heard.values.size(), 100u);  // a thousandth passed at least every 40 items of any thread
}

class FileProgress : public test::ScratchFolder {};

// The octahedron at level 7: 131,072 triangles, a saved file of about 8 MB.
rgb::Mesh fine_octahedron() {
    rgb::Mesh mesh = build_mesh(read_obj_text(test::kOctahedron, "octahedron.obj"));
    rgb::refine_uniform(mesh, 7);
    return mesh;
}

TEST_F(FileProgress, SavingAndReadingASavedFileReportGrowingFractionsEndingAtOne) {
    const rgb::Mesh mesh = fine_octahedron();
    Heard saving;
    SaveOptions options;
    options.progress = rgb::ProgressSpan(&saving.progress);
    save_mesh(mesh, path("fine.obj"), options);
    expect_grows_to_one(saving.values);
    // One report per 4096 of the 65,538 v, 131,072 f and 8,192 state lines at least.
    EXPECT_GE(saving.values.size(), 40u);

    Heard reading;
    const rgb::Mesh loaded = load_mesh(path("fine.obj"), nullptr, {.progress = rgb::ProgressSpan(&reading.progress)});
    EXPECT_TRUE(rgbtest::same_mesh(loaded, mesh));
    expect_grows_to_one(reading.values);
    // One report per 4096 of the 205k lines parsed, and one per pass of the restore.
    EXPECT_GE(reading.values.size(), 40u);
}

// The parse in blocks on several threads (files over 8 MB on two cores) counts every block's bytes.
TEST_F(FileProgress, ParsingInBlocksCountsTheBytesOfEveryBlock) {
    const std::string text = format_obj(fine_octahedron(), {});
    Heard parsing;
    const ObjRecords records = parse_obj_in_blocks(text, "fine.obj", 3, rgb::ProgressSpan(&parsing.progress));
    EXPECT_EQ(records.polygons.size(), 131072u);
    expect_grows_to_one(parsing.values);
    EXPECT_GE(parsing.values.size(), 40u);
}

TEST_F(FileProgress, AFileThatFailsToReadNeverReportsTheEnd) {
    write("broken.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    Heard reading;
    EXPECT_THROW(load_mesh(path("broken.obj"), nullptr, {.progress = rgb::ProgressSpan(&reading.progress)}), ObjError);
    EXPECT_LT(reading.progress.fraction(), 1.0);
}

}  // namespace
}  // namespace rgbio
