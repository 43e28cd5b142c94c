// The hand tools in window terms: grabbing only the cloth, the grab plane, cut strokes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <random>
#include <set>

#include "app/hand_tools.h"
#include "sim/build/topology_edits.h"

namespace weft::app {
namespace {

// A 5x5 vertical sheet 0.4 m wide centred on the view of a camera 2 m in front of it.
Simulation facing_sheet() {
    Scene scene;
    scene.cloth.rows = 5;
    scene.cloth.cols = 5;
    scene.cloth.spacing = 0.1;
    scene.cloth.origin = {-0.2, 0.2, 0.0};
    return Simulation(scene);
}

raster::Camera facing_camera() {
    return raster::make_camera({0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 0.0f}, 50.0f);
}

TEST(HandTools, TheCursorOverTheSheetFindsItAndTheBackgroundDoesNot) {
    const Simulation sim = facing_sheet();
    const raster::Camera camera = facing_camera();
    auto hit = cloth_under_cursor(sim.cloth(), camera, 800, 600, {400.0f, 300.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->particle, 2u * 5 + 2);  // the centre particle
    EXPECT_FALSE(cloth_under_cursor(sim.cloth(), camera, 800, 600, {50.0f, 50.0f}).has_value());
}

TEST(HandTools, TheGrabPlaneKeepsTheGrabDepth) {
    const raster::Camera camera = facing_camera();
    const Vec3 anchor(0.0, 0.0, 0.0);
    auto point = point_on_grab_plane(camera, 800, 600, {600.0f, 300.0f}, anchor);
    ASSERT_TRUE(point.has_value());
    EXPECT_NEAR(point->z, 0.0, 1e-6);  // same depth as the anchor
    EXPECT_GT(point->x, 0.2);          // to the right, where the cursor is
    EXPECT_NEAR(point->y, 0.0, 1e-6);
}

// A spring standing still: whether two segments cross.
bool crosses(const glm::vec2& from, const glm::vec2& to, const glm::vec2& a, const glm::vec2& b) {
    return cursor_passes_spring(from, to, {a, b}, {a, b});
}

TEST(HandTools, AStillSpringIsPassedOnlyWhenTheStrokeCrossesIt) {
    EXPECT_TRUE(crosses({0, 0}, {2, 2}, {0, 2}, {2, 0}));
    EXPECT_FALSE(crosses({0, 0}, {1, 1}, {2, 0}, {3, 1}));
    EXPECT_FALSE(crosses({0, 0}, {2, 0}, {0, 1}, {2, 1}));       // parallel
    EXPECT_FALSE(crosses({0, 0}, {2, 0}, {1, 0.001f}, {1, 5}));  // stops short of the stroke
    EXPECT_FALSE(crosses({0, 0}, {2, 0}, {0, 0}, {2, 0}));       // along it: nothing crossed
    // A motion event that lands exactly on a spring: the stroke's two segments meet there,
    // and touching counts, so neither end of the join lets the spring through.
    EXPECT_TRUE(crosses({0, 0}, {1, 0}, {1, -1}, {1, 1}));
    EXPECT_TRUE(crosses({1, 0}, {2, 0}, {1, -1}, {1, 1}));
}

// The spring: the sheet swung toward the cursor between two motion events, so the
// spring went from ahead of the cursor to behind where it had been; against the spring's new
// place alone the stroke's segment crossed nothing.
TEST(HandTools, ASpringThatSwungAcrossTheCursorIsPassed) {
    const ScreenSegment ahead{{10, -5}, {10, 5}}, behind{{-10, -5}, {-10, 5}};
    EXPECT_FALSE(crosses({0, 0}, {5, 0}, behind.a, behind.b));
    EXPECT_TRUE(cursor_passes_spring({0, 0}, {5, 0}, ahead, behind));
    // Moving the same way as the cursor and faster, it stays ahead: not passed.
    const ScreenSegment further{{30, -5}, {30, 5}};
    EXPECT_FALSE(cursor_passes_spring({0, 0}, {5, 0}, ahead, further));
    // Swinging across the cursor's path after the cursor went by: not passed either.
    EXPECT_FALSE(cursor_passes_spring({0, 0}, {5, 0}, {{-3, 20}, {-3, 30}}, {{-3, -5}, {-3, 5}}));
}

// The independent truth: step time finely, and say whether the cursor went from one side of
// the spring to the other while over it (passed), or how near it ever came (to say a pass was
// made up).
struct Sampled {
    bool passed = false;
    double nearest = 1e30;  // px
};

Sampled sample_pass(const glm::vec2& from, const glm::vec2& to, const ScreenSegment& before,
                    const ScreenSegment& now) {
    constexpr int steps = 20000;
    Sampled result;
    double last_side = 0.0;
    for (int k = 0; k <= steps; ++k) {
        const double t = static_cast<double>(k) / steps;
        const glm::dvec2 a = glm::mix(glm::dvec2(before.a), glm::dvec2(now.a), t);
        const glm::dvec2 b = glm::mix(glm::dvec2(before.b), glm::dvec2(now.b), t);
        const glm::dvec2 p = glm::mix(glm::dvec2(from), glm::dvec2(to), t);
        const glm::dvec2 d = b - a;
        const double along = std::clamp(glm::dot(p - a, d) / glm::dot(d, d), 0.0, 1.0);
        result.nearest = std::min(result.nearest, glm::length(p - (a + along * d)));
        const double side = d.x * (p - a).y - d.y * (p - a).x;
        const double strictly_along = glm::dot(p - a, d) / glm::dot(d, d);
        // Away from the ends, where one time step could carry the crossing off the spring.
        if (k > 0 && side * last_side < 0.0 && strictly_along > 0.01 && strictly_along < 0.99 &&
            glm::length(d) > 1.0)
            result.passed = true;
        last_side = side;
    }
    return result;
}

TEST(HandTools, PassingAMovingSpringAgreesWithFineTimeSteps) {
    std::mt19937 random(18);
    std::uniform_real_distribution<float> coordinate(-50.0f, 50.0f);
    auto point = [&] { return glm::vec2(coordinate(random), coordinate(random)); };
    int passes = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const glm::vec2 from = point(), to = point();
        const ScreenSegment before{point(), point()}, now{point(), point()};
        const bool passed = cursor_passes_spring(from, to, before, now);
        const Sampled truth = sample_pass(from, to, before, now);
        // A sign change seen over the spring is a pass; a pass claimed must come within the
        // sampling's resolution (relative speeds up to 300 px over 20000 steps).
        if (truth.passed) {
            EXPECT_TRUE(passed) << "trial " << trial;
        }
        if (passed) {
            EXPECT_LT(truth.nearest, 0.05) << "trial " << trial;
        }
        passes += passed;
    }
    EXPECT_GT(passes, 300);  // the trials exercise both answers
}

TEST(HandTools, AVerticalStrokeThroughTheMiddleCutsTheHorizontalSpringsItCrosses) {
    Simulation sim = facing_sheet();
    const std::size_t before = sim.cloth().spring_count();
    // From above the sheet to below it, between columns 1 and 2 (x = -0.05 m).
    const float x = 400.0f - 0.05f * 300.0f / (2.0f * std::tan(25.0f * 3.14159265f / 180.0f));
    const std::size_t cut =
        cut_along_stroke(sim, facing_camera(), 800, 600, {x, 50.0f}, {x, 550.0f});
    EXPECT_EQ(cut, 5u);  // the structural spring (r, 1)-(r, 2) of each of the 5 rows
    EXPECT_EQ(sim.cloth().spring_count(), before - 5);
}

// Whether segments p0-p1 and q0-q1 cross, solved as p0 + s (p1 - p0) = q0 + t (q1 - q0).
bool solved_crossing(const glm::vec2& p0, const glm::vec2& p1, const glm::vec2& q0,
                     const glm::vec2& q1) {
    const glm::dvec2 u = glm::dvec2(p1) - glm::dvec2(p0), v = glm::dvec2(q1) - glm::dvec2(q0);
    const glm::dvec2 w = glm::dvec2(q0) - glm::dvec2(p0);
    const double determinant = u.x * -v.y - u.y * -v.x;
    if (determinant == 0.0) return false;
    const double s = (w.x * -v.y - w.y * -v.x) / determinant;
    const double t = (u.x * w.y - u.y * w.x) / determinant;
    return s >= 0.0 && s <= 1.0 && t >= 0.0 && t <= 1.0;
}

// The issue: a right-drag well past both edges of the sheet left one spring. Jagged strokes
// of many segments, from left of the sheet to right of it, cut every spring one of their
// segments crosses (checked one by one), so no spring joins a particle above the stroke to
// one below it: the lower piece falls.
TEST(HandTools, AStrokePastBothEdgesCutsEverySpringItCrosses) {
    Scene scene;
    scene.cloth.rows = 24;
    scene.cloth.cols = 24;
    scene.cloth.spacing = 0.025;
    scene.cloth.origin = {-0.2875, 0.2875, 0.0};  // centred on the camera's target
    std::mt19937 random(9);
    std::uniform_real_distribution<float> wobble(-12.0f, 12.0f), step(3.0f, 40.0f);
    for (int stroke = 0; stroke < 20; ++stroke) {
        Simulation sim(scene);
        const raster::Camera camera = facing_camera();
        std::vector<glm::vec2> points{{150.0f, 230.0f + 7.0f * static_cast<float>(stroke)}};
        while (points.back().x < 650.0f)
            points.push_back(points.back() + glm::vec2(step(random), wobble(random)));
        const ScreenPoints on_screen = particles_on_screen(sim.cloth(), camera, 800, 600);
        std::set<std::uint64_t> expected;
        for (const SpringGroup& group : sim.cloth().topology().spring_groups)
            for (const Spring& s : group.springs)
                for (std::size_t k = 0; k + 1 < points.size(); ++k)
                    if (solved_crossing(points[k], points[k + 1], *on_screen[s.i], *on_screen[s.j]))
                        expected.insert(edge_key(s.i, s.j));
        std::set<std::uint64_t> cut;
        for (std::size_t k = 0; k + 1 < points.size(); ++k)
            for (const std::uint64_t key :
                 springs_along_stroke(sim.cloth(), camera, 800, 600, points[k], points[k + 1]))
                cut.insert(key);
        EXPECT_EQ(cut, expected) << "stroke " << stroke;
        for (std::size_t k = 0; k + 1 < points.size(); ++k)
            cut_along_stroke(sim, camera, 800, 600, points[k], points[k + 1]);
        // The stroke goes left to right: above it is above its height at the particle's x.
        auto above = [&](const glm::vec2& p) {
            std::size_t k = 0;
            while (points[k + 1].x < p.x) ++k;
            const float along = (p.x - points[k].x) / (points[k + 1].x - points[k].x);
            return p.y < glm::mix(points[k].y, points[k + 1].y, along);
        };
        std::size_t joining = 0, below = 0;
        for (std::size_t p = 0; p < on_screen.size(); ++p) below += !above(*on_screen[p]);
        for (const SpringGroup& group : sim.cloth().topology().spring_groups)
            for (const Spring& s : group.springs)
                joining += above(*on_screen[s.i]) != above(*on_screen[s.j]);
        EXPECT_GT(below, 0u) << "stroke " << stroke;
        EXPECT_EQ(joining, 0u) << "stroke " << stroke;
    }
}

}  // namespace
}  // namespace weft::app
