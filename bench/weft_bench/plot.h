// Line plots as PNG files, drawn with weft's own framebuffer: log or linear axes with decade
// ticks, labelled axes, a title and a legend. Enough for work-precision diagrams and stability
// sweeps without a plotting package.
#pragma once

#include <string>
#include <vector>

#include "raster/colour.h"
#include "raster/framebuffer.h"

namespace weft::bench {

struct PlotPoint {
    double x, y;
};

struct PlotSeries {
    std::string label;
    raster::Rgba8 colour;
    std::vector<PlotPoint>
        points;           // drawn in order; non-finite or non-positive (on a log axis) skipped
    bool dashed = false;  // e.g. a prediction beside a measurement
    bool markers = true;
};

struct PlotSpec {
    std::string title;
    std::string x_label;
    std::string y_label;
    bool log_x = true;
    bool log_y = true;
    std::vector<PlotSeries> series;
    std::vector<std::string> notes;  // extra lines under the legend (e.g. "x: diverged")
    int width = 1100;                // pixels: the least; a wide legend widens the image
    int height = 680;
};

// Where a plot's parts go, in pixels. The legend's column, right of the data area, is as wide
// as its longest line (long notes wrap), so no label is cut at the image's edge; the image
// widens rather than squeeze the data area below a readable width.
struct PlotLayout {
    int width, height;               // the image
    int left, right, top, bottom;    // the data area
    std::vector<std::string> notes;  // spec.notes, wrapped to the legend's column
};
PlotLayout plot_layout(const PlotSpec& spec);

// The plot as an image. Series that coincide on the page (a later one over an earlier one,
// point for point, as three integrators with the same stability limit do) stay visible: the
// one drawn first is drawn wider and with larger markers, so it shows as a band around the
// next; and each series has its own marker shape, in the legend as on the lines.
raster::Framebuffer render_plot(const PlotSpec& spec);

// Writes the plot; false with `error` set if the file cannot be written.
bool write_plot_png(const PlotSpec& spec, const std::string& path, std::string* error);

// A palette of distinguishable colours, one per integrator.
raster::Rgba8 series_colour(int index);

}  // namespace weft::bench
