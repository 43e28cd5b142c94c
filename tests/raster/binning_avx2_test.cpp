// Binning's AVX2 classification (raster/binning_avx2.h) against the scalar binning it stands
// in for (bin_coverage): for every lane it decides, the same coverage, facing, box and weights
// to the bit, or the same rows; the lanes it leaves undecided are only those it must (an index
// out of range, a triangle that needs clipping, an extent of more than 1024/256 pixel).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "raster/binning_avx2.h"
#include "raster/camera.h"
#include "raster/clipping.h"
#include "raster/mesh_renderer.h"
#include "raster/triangle_setup.h"
#include "raster/vector_isa.h"
#include "raster_test_support.h"

namespace weft::raster {
namespace {

// The lane masks name each lane once at most, and the undecided ones are counted.
void expect_lane_masks_consistent(const BinningGroup& group, std::size_t first) {
    EXPECT_EQ(group.undecided_count, std::popcount(group.undecided_lanes)) << "triangle " << first;
    EXPECT_EQ(group.tiny_lanes & group.box_lanes, 0u) << "triangle " << first;
    EXPECT_EQ(group.tiny_lanes & group.undecided_lanes, 0u) << "triangle " << first;
    EXPECT_EQ(group.box_lanes & group.undecided_lanes, 0u) << "triangle " << first;
    EXPECT_EQ((group.tiny_lanes | group.box_lanes | group.undecided_lanes) >> binning_group_size,
              0u)
        << "triangle " << first;
}

TEST(BinningAvx2, DecidesEachLaneAsTheScalarBinningDoes) {
    if (!avx2_supported()) GTEST_SKIP() << "this CPU or build has no AVX2";
    constexpr int width = 40, height = 30;
    const PixelRect viewport{0, 0, width, height};
    std::mt19937 rng(20261127);
    std::uniform_int_distribution<int> shape(0, 6);
    std::uniform_int_distribution<std::int64_t> anywhere(-4 * 256, (width + 4) * 256);
    std::vector<WindowVertex> window;
    std::vector<std::uint32_t> outcodes;
    std::vector<TriangleIndices> triangles;
    // Triangles of every kind binning meets: tiny and small ones anywhere (across the edges of
    // the viewport too), slivers of zero area, large ones, and large ones whose only covered
    // centres are a corner's 2×2, with vertices hundreds of pixels away.
    auto add_vertex = [&](std::int64_t x, std::int64_t y, std::uint32_t outcode) {
        window.push_back({x, y, 0.5f, 1.0f});
        outcodes.push_back(outcode);
        return static_cast<std::uint32_t>(window.size() - 1);
    };
    for (int trial = 0; trial < 16000; ++trial) {
        const std::int64_t x = anywhere(rng), y = anywhere(rng);
        const int kind = shape(rng);
        const std::int64_t reach = kind <= 3 ? 300 : kind == 4 ? 500 : 3000;
        std::uniform_int_distribution<std::int64_t> offset(-reach, reach);
        std::array<std::uint32_t, 3> corners;
        if (kind == 6) {
            // A vertex just inside a corner of the viewport, two 200 pixels outside it along
            // its sides: inside the viewport it covers at most the corner's 2×2 centres.
            const bool right = trial % 2 == 1, bottom = trial % 4 >= 2;
            const std::int64_t inward_x = right ? -1 : 1, inward_y = bottom ? -1 : 1;
            const std::int64_t cx = right ? width * 256 - 400 : 400;
            const std::int64_t cy = bottom ? height * 256 - 400 : 400;
            const std::int64_t far = 200 * 256, near = 128;
            corners = {add_vertex(cx, cy, 0),
                       add_vertex(cx - inward_x * far, cy - inward_y * near, 0),
                       add_vertex(cx - inward_x * near, cy - inward_y * far, 0)};
        } else {
            for (int c = 0; c < 3; ++c) {
                std::uint32_t outcode = 0;
                if (trial % 97 == 0 && c == 1) outcode = outside_near;  // needs clipping
                if (trial % 89 == 0) outcode = outside_left;            // all three: culled
                corners[c] = add_vertex(x + offset(rng), y + offset(rng), outcode);
            }
            if (kind == 3) {  // collinear: zero area
                const WindowVertex a = window[corners[0]], b = window[corners[1]];
                window[corners[2]] = {2 * b.x - a.x, 2 * b.y - a.y, 0.5f, 1.0f};
            }
        }
        if (trial % 101 == 0) corners[2] = 1u << 30;  // an index out of range
        triangles.push_back({corners[0], corners[1], corners[2]});
    }

    int decided_tiny = 0, decided_rows = 0, decided_nothing = 0, undecided = 0, far_corners = 0;
    BinningGroup group;
    for (std::size_t first = 0; first + binning_group_size <= triangles.size();
         first += binning_group_size) {
        classify_for_binning_avx2(triangles.data() + first,
                                  static_cast<std::uint32_t>(window.size()), outcodes.data(),
                                  window.data(), width, height, group);
        expect_lane_masks_consistent(group, first);
        for (int lane = 0; lane < binning_group_size; ++lane) {
            const TriangleIndices& t = triangles[first + lane];
            const bool in_range = t[2] < window.size();
            const TriangleOutcodes codes{outcodes[t[0]], outcodes[t[1]],
                                         in_range ? outcodes[t[2]] : 0u};
            if (group.kind(lane) == BinningGroup::undecided) {
                ++undecided;
                if (!in_range || codes.needs_clipping()) continue;
                // Left to the scalar path only for an extent of more than 1024/256 px.
                std::int64_t extent = 0;
                for (const auto axis : {&WindowVertex::x, &WindowVertex::y}) {
                    const std::int64_t values[3] = {window[t[0]].*axis, window[t[1]].*axis,
                                                    window[t[2]].*axis};
                    extent = std::max(extent, *std::max_element(values, values + 3) -
                                                  *std::min_element(values, values + 3));
                }
                EXPECT_GT(extent, 1024) << "triangle " << first + lane;
                BinnedCoverage coverage;
                bin_coverage(window[t[0]], window[t[1]], window[t[2]], viewport, coverage);
                if (coverage.tiny) ++far_corners;
                continue;
            }
            ASSERT_TRUE(in_range) << "triangle " << first + lane;
            ASSERT_FALSE(codes.needs_clipping() && !codes.culled()) << "triangle " << first + lane;
            BinnedCoverage coverage;
            if (!codes.culled())
                bin_coverage(window[t[0]], window[t[1]], window[t[2]], viewport, coverage);
            if (group.kind(lane) == BinningGroup::draws_nothing) {
                ++decided_nothing;
                EXPECT_TRUE(coverage.empty()) << "triangle " << first + lane;
                continue;
            }
            if (group.kind(lane) == BinningGroup::box_rows) {
                ++decided_rows;
                EXPECT_FALSE(coverage.tiny) << "triangle " << first + lane;
                EXPECT_EQ(group.y_begin[lane], coverage.first) << "triangle " << first + lane;
                EXPECT_EQ(group.y_end[lane] - 1, coverage.last) << "triangle " << first + lane;
                continue;
            }
            ++decided_tiny;
            ASSERT_TRUE(coverage.tiny) << "triangle " << first + lane;
            EXPECT_EQ(group.covered[lane], coverage.covered) << "triangle " << first + lane;
            EXPECT_EQ(group.front_facing[lane] != 0, coverage.front_facing);
            EXPECT_EQ(group.x_begin[lane], coverage.x_begin);
            EXPECT_EQ(group.y_begin[lane], coverage.y_begin);
            for (unsigned left = coverage.covered; left != 0; left &= left - 1) {
                const int k = std::countr_zero(left);
                for (int i = 0; i < 3; ++i)
                    EXPECT_EQ(group.weight[k][i][lane], coverage.weights[k][i])
                        << "triangle " << first + lane;
            }
        }
    }
    // Every kind of lane, many times over.
    EXPECT_GT(decided_tiny, 1000);
    EXPECT_GT(decided_rows, 500);
    EXPECT_GT(decided_nothing, 1000);
    EXPECT_GT(undecided, 1000);
    EXPECT_GT(far_corners, 100);
}

// A whole grid's groups classified from loaded corners (classify_grid_group_avx2) against the
// same groups gathered: lane for lane, the same kind and, where the lane says, the same box,
// coverage, facing and weights. A fine wavy sheet seen whole (tiny triangles), close up
// (larger ones, some cut by the near plane) and partly off screen; a sheet 7 columns wide,
// whose rows of 6 cells leave groups that do not fit.
TEST(BinningAvx2, LoadsAWholeGridsCornersAsItGathersThem) {
    if (!avx2_supported()) GTEST_SKIP() << "this CPU or build has no AVX2";
    const int width = 320, height = 200;
    std::size_t compared = 0, tiny = 0, rows = 0, undecided = 0, unfit = 0;
    for (const int cols : {97, 7}) {
        const int grid_rows = 61;
        TriangleMesh sheet;
        for (int r = 0; r < grid_rows; ++r) {
            for (int c = 0; c < cols; ++c) {
                const float u = static_cast<float>(c) / 96.0f, v = static_cast<float>(r) / 60.0f;
                sheet.positions.push_back(
                    {u - 0.5f, 0.1f * std::sin(9.0f * u) * std::cos(7.0f * v), v - 0.5f});
                sheet.normals.push_back({0.0f, 1.0f, 0.0f});
                sheet.uvs.push_back({u, v});
            }
        }
        sheet.triangles = testing::whole_grid_triangles(grid_rows, cols);
        MeshView view = sheet.view();
        view.grid_cols = cols;
        const Camera cameras[] = {make_camera({0.2f, 2.5f, 1.5f}, {0.0f, 0.0f, 0.0f}, 50.0f),
                                  make_camera({0.05f, 0.12f, 0.1f}, {0.0f, 0.0f, -0.3f}, 70.0f),
                                  make_camera({0.9f, 0.6f, 0.9f}, {0.4f, 0.0f, 0.3f}, 40.0f)};
        for (const Camera& camera : cameras) {
            PreparedMesh prepared;
            ASSERT_TRUE(prepare_mesh(camera, width, height, view, SurfaceStyle{}, prepared));
            ASSERT_EQ(prepared.mesh.grid_cols, cols);
            const auto count = static_cast<std::uint32_t>(prepared.clip.size());
            for (std::size_t first = 0; first + binning_group_size <= sheet.triangles.size();
                 first += binning_group_size) {
                if (!grid_group_fits(first, cols)) {
                    ++unfit;
                    continue;
                }
                BinningGroup loaded, gathered;
                classify_grid_group_avx2(first, cols, prepared.outcodes.data(),
                                         prepared.snapped_x.data(), prepared.snapped_y.data(),
                                         width, height, loaded);
                classify_for_binning_avx2(sheet.triangles.data() + first, count,
                                          prepared.outcodes.data(), prepared.window.data(), width,
                                          height, gathered);
                expect_lane_masks_consistent(loaded, first);
                expect_lane_masks_consistent(gathered, first);
                for (int lane = 0; lane < binning_group_size; ++lane) {
                    ++compared;
                    ASSERT_EQ(loaded.kind(lane), gathered.kind(lane)) << first + lane;
                    if (gathered.kind(lane) == BinningGroup::undecided) ++undecided;
                    if (gathered.kind(lane) == BinningGroup::box_rows) {
                        ++rows;
                        EXPECT_EQ(loaded.y_begin[lane], gathered.y_begin[lane]) << first + lane;
                        EXPECT_EQ(loaded.y_end[lane], gathered.y_end[lane]) << first + lane;
                    }
                    if (gathered.kind(lane) != BinningGroup::tiny) continue;
                    ++tiny;
                    EXPECT_EQ(loaded.covered[lane], gathered.covered[lane]) << first + lane;
                    EXPECT_EQ(loaded.front_facing[lane], gathered.front_facing[lane]);
                    EXPECT_EQ(loaded.x_begin[lane], gathered.x_begin[lane]) << first + lane;
                    EXPECT_EQ(loaded.y_begin[lane], gathered.y_begin[lane]) << first + lane;
                    for (int k = 0; k < tiny_box_side * tiny_box_side; ++k)
                        for (int i = 0; i < 3; ++i)
                            EXPECT_EQ(loaded.weight[k][i][lane], gathered.weight[k][i][lane]);
                }
            }
        }
    }
    EXPECT_GT(compared, 20000u);
    EXPECT_GT(tiny, 3000u);
    EXPECT_GT(rows, 1000u);
    EXPECT_GT(undecided, 100u);
    EXPECT_GT(unfit, 50u);
}

}  // namespace
}  // namespace weft::raster
