// A small, dependency-free SVG line/scatter plot for the bench report: axes with ticks, one
// polyline (solid or dashed) and/or markers per series, a legend, and text labels.
// Coordinates are plotted as given; the bench passes log10 values and sets log_axes so that
// ticks read 1e-16, 1e-8, ... Non-finite points are skipped (a series breaks there).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace linkproof {

struct SvgSeries {
  std::string name;
  std::string color = "#1f77b4";
  bool dashed = false;
  bool line = true;
  bool markers = true;
  std::vector<std::pair<double, double>> points;
};

struct SvgLabel {
  double x = 0, y = 0;
  std::string text;
};

struct SvgPlot {
  std::string title, x_label, y_label;
  bool log_axes = true;  ///< tick labels 10^k for coordinate k
  std::vector<SvgSeries> series;
  std::vector<SvgLabel> labels;

  /// The complete SVG document.
  std::string render() const;
};

/// SVG text and attributes: report::html_escape (report/escape.h), the one markup escaper.
std::string svg_escape(const std::string& s);

/// A distinct colour per index (a fixed categorical palette).
std::string palette_color(size_t index);

}  // namespace linkproof
