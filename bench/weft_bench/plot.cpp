#include "plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include <stb/stb_easy_font.h>

#include "raster/framebuffer.h"
#include "raster/png_writer.h"

namespace weft::bench {
namespace {

constexpr int text_scale = 2;  // stb_easy_font glyphs are ~7 px tall; doubled for reading

struct Axis {
    bool log;
    double min, max;  // in data units
    int pixel_begin, pixel_end;
    double map(double value) const {
        const double a = log ? std::log10(value) : value;
        const double lo = log ? std::log10(min) : min, hi = log ? std::log10(max) : max;
        return pixel_begin + (a - lo) / (hi - lo) * (pixel_end - pixel_begin);
    }
    bool usable(double value) const { return std::isfinite(value) && (!log || value > 0.0); }
};

void fill_rect(raster::Framebuffer& fb, int x0, int y0, int x1, int y1, raster::Rgba8 colour) {
    for (int y = std::max(0, y0); y < std::min(fb.height(), y1); ++y)
        for (int x = std::max(0, x0); x < std::min(fb.width(), x1); ++x) fb.colour(x, y) = colour;
}

void draw_text(raster::Framebuffer& fb, int x, int y, const std::string& text,
               raster::Rgba8 colour) {
    static char buffer[200000];
    std::string copy = text;
    const int quads = stb_easy_font_print(0.0f, 0.0f, copy.data(), nullptr, buffer, sizeof buffer);
    for (int q = 0; q < quads; ++q) {
        const float* v = reinterpret_cast<const float*>(buffer + q * 4 * 16);
        // Each quad is an axis-aligned rectangle: corners 0 and 2 are opposite.
        const float* c = reinterpret_cast<const float*>(buffer + q * 4 * 16 + 2 * 16);
        fill_rect(fb, x + static_cast<int>(v[0] * text_scale),
                  y + static_cast<int>(v[1] * text_scale), x + static_cast<int>(c[0] * text_scale),
                  y + static_cast<int>(c[1] * text_scale), colour);
    }
}

int text_width(const std::string& text) {
    std::string copy = text;
    return stb_easy_font_width(copy.data()) * text_scale;
}

// A 2-pixel-wide line by DDA; `dashed` skips every other 8-pixel stretch.
void draw_line(raster::Framebuffer& fb, double x0, double y0, double x1, double y1,
               raster::Rgba8 colour, bool dashed, int width = 2) {
    const double steps = std::max(std::abs(x1 - x0), std::abs(y1 - y0));
    const int count = static_cast<int>(std::ceil(steps)) + 1;
    for (int s = 0; s < count; ++s) {
        if (dashed && (s / 8) % 2) continue;
        const double t = count > 1 ? static_cast<double>(s) / (count - 1) : 0.0;
        const int x = static_cast<int>(std::lround(x0 + t * (x1 - x0)));
        const int y = static_cast<int>(std::lround(y0 + t * (y1 - y0)));
        fill_rect(fb, x - width / 2, y - width / 2, x - width / 2 + width, y - width / 2 + width,
                  colour);
    }
}

std::string tick_label(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// Ticks: every decade on a log axis (or every 1-2-5 step when the range is under a decade);
// about 6 round steps on a linear one.
std::vector<double> ticks(const Axis& axis) {
    std::vector<double> result;
    if (axis.log) {
        for (double decade = std::pow(10.0, std::floor(std::log10(axis.min)));
             decade <= axis.max * 1.0001; decade *= 10.0) {
            for (double m : {1.0, 2.0, 5.0}) {
                const double v = decade * m;
                const bool fine = axis.max / axis.min < 30.0;
                if ((m == 1.0 || fine) && v >= axis.min * 0.9999 && v <= axis.max * 1.0001)
                    result.push_back(v);
            }
        }
    } else {
        const double raw = (axis.max - axis.min) / 6.0;
        const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
        const double step = raw / magnitude < 2   ? 2 * magnitude
                            : raw / magnitude < 5 ? 5 * magnitude
                                                  : 10 * magnitude;
        for (double v = std::ceil(axis.min / step) * step; v <= axis.max + 1e-12 * step; v += step)
            result.push_back(v);
    }
    return result;
}

// Data range of all usable points, padded; log axes snap outward to decades.
void fit_range(Axis& axis, const std::vector<double>& values) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (double v : values) {
        if (!axis.usable(v)) continue;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    if (!std::isfinite(lo)) lo = 1.0, hi = 10.0;
    if (axis.log) {
        if (hi / lo < 10.0) {
            const double centre = std::sqrt(lo * hi);
            lo = centre / 4.0, hi = centre * 4.0;
        }
        axis.min = std::pow(10.0, std::floor(std::log10(lo)));
        axis.max = std::pow(10.0, std::ceil(std::log10(hi)));
    } else {
        const double pad = hi > lo ? 0.05 * (hi - lo) : 1.0;
        axis.min = lo - pad, axis.max = hi + pad;
    }
}

// Each series' marker has its own shape (by its place in the plot), so a series can be
// told by its markers where colours sit close or lines lie on top of each other.
enum class Marker { square, circle, triangle, diamond };

Marker marker_shape(int series_index) {
    return static_cast<Marker>(series_index % 4);
}

// A filled marker of half-size `r` pixels centred on (x, y).
void draw_marker(raster::Framebuffer& fb, double x, double y, int r, Marker shape,
                 raster::Rgba8 colour) {
    const int cx = static_cast<int>(std::lround(x)), cy = static_cast<int>(std::lround(y));
    for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
            const bool inside = shape == Marker::square     ? true
                                : shape == Marker::circle   ? dx * dx + dy * dy <= r * r
                                : shape == Marker::triangle ? 2 * std::abs(dx) <= dy + r  // apex up
                                                            : std::abs(dx) + std::abs(dy) <= r;
            if (inside) fill_rect(fb, cx + dx, cy + dy, cx + dx + 1, cy + dy + 1, colour);
        }
    }
}

bool usable(const PlotPoint& p, const Axis& x_axis, const Axis& y_axis) {
    return x_axis.usable(p.x) && y_axis.usable(p.y);
}

// Whether `later`, drawn over `earlier`, would hide it: the same points, each within a few
// pixels of its partner on the page.
bool hides(const PlotSeries& later, const PlotSeries& earlier, const Axis& x_axis,
           const Axis& y_axis) {
    if (later.points.size() != earlier.points.size()) return false;
    constexpr double near = 3.0;  // px
    bool any = false;
    for (std::size_t k = 0; k < earlier.points.size(); ++k) {
        const PlotPoint &a = earlier.points[k], &b = later.points[k];
        const bool drawn = usable(a, x_axis, y_axis);
        if (drawn != usable(b, x_axis, y_axis)) return false;
        if (!drawn) continue;
        if (std::abs(x_axis.map(a.x) - x_axis.map(b.x)) > near ||
            std::abs(y_axis.map(a.y) - y_axis.map(b.y)) > near)
            return false;
        any = true;
    }
    return any;
}

// For each series, how many drawn after it would hide it: it is drawn that much wider (with
// larger markers), so each shows as a band around the ones over it.
std::vector<int> hidden_under(const std::vector<PlotSeries>& series, const Axis& x_axis,
                              const Axis& y_axis) {
    std::vector<int> count(series.size(), 0);
    for (std::size_t i = 0; i < series.size(); ++i)
        for (std::size_t j = i + 1; j < series.size(); ++j)
            if (hides(series[j], series[i], x_axis, y_axis)) ++count[i];
    return count;
}

// `note` broken at spaces into lines at most `widest` pixels wide (a longer word stays
// whole); continuation lines keep the note's indent.
std::vector<std::string> wrapped(const std::string& note, int widest) {
    const std::size_t first = note.find_first_not_of(' ');
    if (first == std::string::npos) return {note};
    const std::string indent = note.substr(0, first);
    std::vector<std::string> lines;
    std::string line = indent;
    std::istringstream words(note.substr(first));
    std::string word;
    while (words >> word) {
        const bool empty = line.size() == indent.size();
        const std::string longer = empty ? line + word : line + " " + word;
        if (!empty && text_width(longer) > widest) {
            lines.push_back(line);
            line = indent + word;
        } else {
            line = longer;
        }
    }
    lines.push_back(line);
    return lines;
}

// The legend, right of the data area: a swatch (line and marker) and a label per series.
constexpr int swatch_gap = 20;       // px from the data area to the swatch, and to the notes
constexpr int label_offset = 58;     // px from the data area to a series' label
constexpr int right_margin = 16;     // px right of the legend's longest line
constexpr int widest_note = 420;     // px, about 35 characters, before a note wraps
constexpr int narrowest_data = 560;  // px: the image widens rather than go below

}  // namespace

PlotLayout plot_layout(const PlotSpec& spec) {
    PlotLayout layout{spec.width, spec.height, 110, 0, 70, spec.height - 70, {}};
    int legend = 0;
    for (const PlotSeries& series : spec.series)
        legend = std::max(legend, label_offset + text_width(series.label));
    for (const std::string& note : spec.notes)
        for (std::string& line : wrapped(note, widest_note)) {
            legend = std::max(legend, swatch_gap + text_width(line));
            layout.notes.push_back(std::move(line));
        }
    layout.width = std::max(spec.width, layout.left + narrowest_data + legend + right_margin);
    layout.right = layout.width - legend - right_margin;
    return layout;
}

raster::Rgba8 series_colour(int index) {
    static const raster::Rgba8 palette[] = {
        {214, 39, 40, 255},  {31, 119, 180, 255}, {44, 160, 44, 255},  {148, 103, 189, 255},
        {255, 127, 14, 255}, {140, 86, 75, 255},  {23, 190, 207, 255}, {127, 127, 127, 255}};
    return palette[index % 8];
}

raster::Framebuffer render_plot(const PlotSpec& spec) {
    const PlotLayout layout = plot_layout(spec);
    raster::Framebuffer fb(layout.width, layout.height);
    const raster::Rgba8 white{255, 255, 255, 255}, black{20, 20, 20, 255}, grid{225, 225, 225, 255};
    fb.clear(white);
    const int left = layout.left, right = layout.right, top = layout.top, bottom = layout.bottom;

    Axis x_axis{spec.log_x, 0, 1, left, right}, y_axis{spec.log_y, 0, 1, bottom, top};
    std::vector<double> xs, ys;
    for (const PlotSeries& series : spec.series)
        for (const PlotPoint& p : series.points)
            if (usable(p, x_axis, y_axis)) xs.push_back(p.x), ys.push_back(p.y);
    fit_range(x_axis, xs);
    fit_range(y_axis, ys);

    for (double t : ticks(x_axis)) {
        const double x = x_axis.map(t);
        draw_line(fb, x, top, x, bottom, grid, false, 1);
        const std::string label = tick_label(t);
        draw_text(fb, static_cast<int>(x) - text_width(label) / 2, bottom + 8, label, black);
    }
    for (double t : ticks(y_axis)) {
        const double y = y_axis.map(t);
        draw_line(fb, left, y, right, y, grid, false, 1);
        const std::string label = tick_label(t);
        draw_text(fb, left - 8 - text_width(label), static_cast<int>(y) - 7, label, black);
    }
    draw_line(fb, left, bottom, right, bottom, black, false, 1);
    draw_line(fb, left, top, left, bottom, black, false, 1);
    draw_text(fb, left, 10, spec.title, black);
    draw_text(fb, (left + right) / 2 - text_width(spec.x_label) / 2, spec.height - 34, spec.x_label,
              black);
    draw_text(fb, 8, top - 32, spec.y_label, black);

    const std::vector<int> under = hidden_under(spec.series, x_axis, y_axis);
    int legend_y = top;
    for (std::size_t s = 0; s < spec.series.size(); ++s) {
        const PlotSeries& series = spec.series[s];
        const Marker shape = marker_shape(static_cast<int>(s));
        const int line_width = 2 + 3 * under[s];
        const int marker_size = 4 + 2 * under[s];
        bool have_previous = false;
        double px = 0, py = 0;
        for (const PlotPoint& p : series.points) {
            if (!usable(p, x_axis, y_axis)) {
                have_previous = false;  // a missing point breaks the line
                continue;
            }
            const double x = x_axis.map(p.x), y = y_axis.map(p.y);
            if (have_previous)
                draw_line(fb, px, py, x, y, series.colour, series.dashed, line_width);
            if (series.markers) draw_marker(fb, x, y, marker_size, shape, series.colour);
            px = x, py = y, have_previous = true;
        }
        const int swatch_left = right + swatch_gap, swatch_right = right + label_offset - 8;
        draw_line(fb, swatch_left, legend_y + 7, swatch_right, legend_y + 7, series.colour,
                  series.dashed);
        if (series.markers)
            draw_marker(fb, 0.5 * (swatch_left + swatch_right), legend_y + 7, 4, shape,
                        series.colour);
        draw_text(fb, right + label_offset, legend_y, series.label, black);
        legend_y += 22;
    }
    for (const std::string& note : layout.notes) {
        legend_y += 6;
        draw_text(fb, right + swatch_gap, legend_y, note, black);
        legend_y += 16;
    }
    return fb;
}

bool write_plot_png(const PlotSpec& spec, const std::string& path, std::string* error) {
    return raster::write_png(render_plot(spec), path, error);
}

}  // namespace weft::bench
