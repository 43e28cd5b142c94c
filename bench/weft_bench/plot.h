// Line plots as PNG files, drawn with weft's own framebuffer: log or linear axes with decade
// ticks, labelled axes, a title and a legend. Enough for work-precision diagrams and stability
// sweeps without a plotting package.
#pragma once

#include <string>
#include <vector>

#include "raster/colour.h"

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
    int width = 1100;                // pixels
    int height = 680;
};

// Writes the plot; false with `error` set if the file cannot be written.
bool write_plot_png(const PlotSpec& spec, const std::string& path, std::string* error);

// A palette of distinguishable colours, one per integrator.
raster::Rgba8 series_colour(int index);

}  // namespace weft::bench
