// weft-bench's plots. Truths read off the image itself: no ink in the image's last columns
// (nothing runs off its edge), and every series' colour on the data area (nothing hidden under
// another series).
#include <gtest/gtest.h>

#include "weft_bench/plot.h"

namespace weft::bench {
namespace {

const raster::Rgba8 white{255, 255, 255, 255};

// Pixels of `colour` inside columns [x0, x1) and rows [y0, y1).
int count_colour(const raster::Framebuffer& fb, raster::Rgba8 colour, int x0, int x1, int y0,
                 int y1) {
    int count = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) count += fb.colour(x, y) == colour;
    return count;
}

// The stability plot's shape: measured and predicted series per integrator, and a note.
PlotSpec stability_like(std::vector<PlotSeries> series, std::vector<std::string> notes) {
    PlotSpec spec;
    spec.title = "Largest stable dt against grid";
    spec.x_label = "particles per side";
    spec.y_label = "dt (s)";
    spec.series = std::move(series);
    spec.notes = std::move(notes);
    return spec;
}

std::vector<PlotPoint> falling_line() {
    return {{10, 3e-3}, {20, 2.9e-3}, {40, 2.85e-3}};
}

TEST(Plot, LegendLabelsAndNotesStayInsideTheImage) {
    // The labels and notes cut at the image's right edge in the published plots.
    const PlotSpec spec = stability_like(
        {{"symplectic-euler predicted", series_colour(1), falling_line(), true, false},
         {"velocity-verlet (order 2.00)", series_colour(3), falling_line()}},
        {"explicit-euler diverged at dt:",
         "  0.001 0.0005 0.00025 0.000125 6.25e-05 3.125e-05 1.5625e-05 7.8125e-06"});
    const raster::Framebuffer fb = render_plot(spec);
    const PlotLayout layout = plot_layout(spec);
    ASSERT_EQ(fb.width(), layout.width);
    const int margin = 8;  // px: the last columns hold no ink
    EXPECT_EQ(count_colour(fb, white, fb.width() - margin, fb.width(), 0, fb.height()),
              margin * fb.height());
    // The legend is there, right of the data area: text in black.
    EXPECT_GT(count_colour(fb, {20, 20, 20, 255}, layout.right, fb.width(), 0, fb.height()), 500);
    // The long list of dts wrapped under the legend instead of widening the image without end.
    EXPECT_GT(layout.notes.size(), spec.notes.size());
    EXPECT_LE(fb.width(), 1400);
}

TEST(Plot, AShortLegendKeepsTheImageAtItsGivenSize) {
    const raster::Framebuffer fb =
        render_plot(stability_like({{"rk4", series_colour(4), falling_line()}}, {}));
    EXPECT_EQ(fb.width(), 1100);
    EXPECT_EQ(fb.height(), 680);
}

TEST(Plot, SeriesOnTopOfEachOtherAllShowOnTheDataArea) {
    // Symplectic Euler, Verlet and velocity Verlet share a stability limit: three lines on
    // the same points, and their predictions likewise (dashed).
    std::vector<PlotSeries> series;
    for (int s = 1; s <= 3; ++s) series.push_back({"measured", series_colour(s), falling_line()});
    for (int s = 1; s <= 3; ++s)
        series.push_back({"predicted",
                          series_colour(s),
                          {{10, 2.5e-3}, {20, 2.4e-3}, {40, 2.3e-3}},
                          true,
                          false});
    const PlotSpec spec = stability_like(series, {});
    const raster::Framebuffer fb = render_plot(spec);
    const PlotLayout layout = plot_layout(spec);
    for (int s = 1; s <= 3; ++s) {
        const int shown = count_colour(fb, series_colour(s), layout.left, layout.right + 1,
                                       layout.top, layout.bottom + 1);
        // A 2-px line across the data area covers over 1000 pixels; a band each side of the
        // line over it, a few hundred at least.
        EXPECT_GT(shown, 300) << "series " << s << " is hidden";
    }
}

TEST(Plot, SeriesThatOnlyCrossStayThin) {
    // Widening is for lines that would hide one another, not for any two that meet.
    const PlotSpec spec =
        stability_like({{"rising", series_colour(0), {{10, 1e-3}, {20, 2e-3}, {40, 4e-3}}},
                        {"falling", series_colour(1), {{10, 4e-3}, {20, 2e-3}, {40, 1e-3}}}},
                       {});
    const raster::Framebuffer fb = render_plot(spec);
    const PlotLayout layout = plot_layout(spec);
    const int rising = count_colour(fb, series_colour(0), layout.left, layout.right + 1, layout.top,
                                    layout.bottom + 1);
    const int falling = count_colour(fb, series_colour(1), layout.left, layout.right + 1,
                                     layout.top, layout.bottom + 1);
    // The same length of line and the same width: within a marker or two of each other.
    EXPECT_NEAR(rising, falling, 0.2 * falling);
}

}  // namespace
}  // namespace weft::bench
