#include "svg_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "report/escape.h"

namespace linkproof {

std::string svg_escape(const std::string& s) { return report::html_escape(s); }

std::string palette_color(size_t index) {
  static const char* colors[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                 "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  return colors[index % (sizeof colors / sizeof colors[0])];
}

namespace {

/// Tick step giving at most ~8 ticks over `span` (1, 2, 5 x 10^k, at least 1 on log axes).
double tick_step(double span, bool integer) {
  const double raw = span / 8;
  const double p = std::pow(10.0, std::floor(std::log10(std::max(raw, 1e-12))));
  double step = p;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) {
      step = m * p;
      break;
    }
  return integer ? std::max(1.0, std::round(step)) : step;
}

std::string tick_text(double v, bool log_axes) {
  if (log_axes) return fmt::format("1e{}", static_cast<long>(std::lround(v)));
  return fmt::format("{:g}", v);
}

}  // namespace

std::string SvgPlot::render() const {
  constexpr double W = 900, H = 560, left = 80, right = 250, top = 50, bottom = 60;
  const double pw = W - left - right, ph = H - top - bottom;
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  const auto extend = [&](double x, double y) {
    if (!std::isfinite(x) || !std::isfinite(y)) return;
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  };
  for (const SvgSeries& s : series)
    for (auto [x, y] : s.points) extend(x, y);
  for (const SvgLabel& l : labels) extend(l.x, l.y);
  if (!std::isfinite(x0)) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  if (x1 - x0 < 1e-9) x0 -= 1, x1 += 1;
  if (y1 - y0 < 1e-9) y0 -= 1, y1 += 1;
  const double xs = tick_step(x1 - x0, log_axes), ys = tick_step(y1 - y0, log_axes);
  x0 = std::floor(x0 / xs) * xs, x1 = std::ceil(x1 / xs) * xs;
  y0 = std::floor(y0 / ys) * ys, y1 = std::ceil(y1 / ys) * ys;
  const auto X = [&](double x) { return left + (x - x0) / (x1 - x0) * pw; };
  const auto Y = [&](double y) { return top + (y1 - y) / (y1 - y0) * ph; };

  std::string o = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n",
      W, H);
  o += fmt::format("<text x=\"{}\" y=\"24\" font-size=\"16\" text-anchor=\"middle\">{}</text>\n", left + pw / 2,
                   svg_escape(title));
  // Grid and ticks.
  for (double x = x0; x <= x1 + xs / 2; x += xs) {
    o += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#e0e0e0\"/>\n", X(x),
                     top, top + ph);
    o += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n", X(x), top + ph + 18,
                     tick_text(x, log_axes));
  }
  for (double y = y0; y <= y1 + ys / 2; y += ys) {
    o += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#e0e0e0\"/>\n", left,
                     Y(y), left + pw);
    o += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{}</text>\n", left - 6, Y(y) + 4,
                     tick_text(y, log_axes));
  }
  o += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"black\"/>\n", left, top,
                   pw, ph);
  o += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n", left + pw / 2, H - 15,
                   svg_escape(x_label));
  o += fmt::format(
      "<text x=\"18\" y=\"{0:.1f}\" text-anchor=\"middle\" transform=\"rotate(-90 18 {0:.1f})\">{1}</text>\n",
      top + ph / 2, svg_escape(y_label));
  // Series.
  for (size_t k = 0; k < series.size(); ++k) {
    const SvgSeries& s = series[k];
    const std::string dash = s.dashed ? " stroke-dasharray=\"6 4\"" : "";
    if (s.line) {
      std::string path;
      bool pen_down = false;
      for (auto [x, y] : s.points) {
        if (!std::isfinite(x) || !std::isfinite(y)) {
          pen_down = false;
          continue;
        }
        path += fmt::format("{}{:.1f},{:.1f} ", pen_down ? "L" : "M", X(x), Y(y));
        pen_down = true;
      }
      if (!path.empty())
        o += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.8\"{}/>\n", path,
                         svg_escape(s.color), dash);
    }
    if (s.markers)
      for (auto [x, y] : s.points)
        if (std::isfinite(x) && std::isfinite(y))
          o += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3.5\" fill=\"{}\"/>\n", X(x), Y(y),
                           svg_escape(s.color));
    // Legend entry.
    const double ly = top + 14 + 18 * static_cast<double>(k);
    o += fmt::format("<line x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\" stroke=\"{3}\" stroke-width=\"2\"{4}/>\n",
                     left + pw + 12, ly, left + pw + 36, svg_escape(s.color), dash);
    o += fmt::format("<text x=\"{}\" y=\"{:.1f}\">{}</text>\n", left + pw + 42, ly + 4, svg_escape(s.name));
  }
  for (const SvgLabel& l : labels)
    if (std::isfinite(l.x) && std::isfinite(l.y))
      o += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"10\">{}</text>\n", X(l.x) + 5, Y(l.y) - 5,
                       svg_escape(l.text));
  o += "</svg>\n";
  return o;
}

}  // namespace linkproof
