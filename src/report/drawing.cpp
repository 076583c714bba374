#include "report/drawing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>

#include "report/escape.h"
#include "svg_plot.h"

namespace linkproof::report {

namespace {

struct Box {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  bool empty() const { return !(x0 <= x1 && y0 <= y1); }
  void add(Point2 p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  bool contains(Point2 p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
};

// The label's base and subscript: "K'_1" -> ("K'", "1"), "A_BA^t" -> ("A", "BA^t").
std::pair<std::string, std::string> split_label(const std::string& label) {
  const auto u = label.find('_');
  if (u == std::string::npos) return {label, ""};
  return {label.substr(0, u), label.substr(u + 1)};
}

std::string svg_label(const std::string& label) {
  const auto [base, sub] = split_label(label);
  // The program's Greek names as letters ("beta_1" -> β₁), as label_tex does for LaTeX.
  static const std::pair<const char*, const char*> greek[] = {{"alpha", "α"}, {"beta", "β"},   {"gamma", "γ"},
                                                               {"omega", "ω"}, {"phi", "φ"},    {"lambda", "λ"},
                                                               {"mu", "μ"}};
  std::string out = svg_escape(base);
  for (const auto& [name, letter] : greek)
    if (base == name) out = letter;
  if (!sub.empty()) out += "<tspan baseline-shift=\"sub\" font-size=\"75%\">" + svg_escape(sub) + "</tspan>";
  return out;
}

const char* dash_of(Stroke s) { return s == Stroke::Dashed ? " stroke-dasharray=\"6 4\"" : ""; }
double width_of(Stroke s) { return s == Stroke::Solid ? 2.0 : 1.0; }

// PDF colour operator arguments "r g b" from "#rrggbb" (black for anything else: the text goes
// into \pdfliteral, so nothing but these digits may).
std::string pdf_rgb(const std::string& hex) {
  if (hex.size() != 7 || hex[0] != '#' ||
      !std::all_of(hex.begin() + 1, hex.end(), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); }))
    return "0 0 0";
  const auto channel = [&](size_t i) { return std::stoi(hex.substr(i, 2), nullptr, 16) / 255.0; };
  return fmt::format("{:.3f} {:.3f} {:.3f}", channel(1), channel(3), channel(5));
}

// The arc of an angle mark as points, radius r, from direction `from` turning to `to`
// by the signed angle between them (ccw positive).
std::vector<Point2> arc_points(const AngleMark& m, double r) {
  const double a0 = std::atan2(m.from.y, m.from.x);
  double sweep = std::atan2(m.from.x * m.to.y - m.from.y * m.to.x, m.from.x * m.to.x + m.from.y * m.to.y);
  std::vector<Point2> pts;
  const int steps = 24;
  for (int k = 0; k <= steps; ++k) {
    const double a = a0 + sweep * k / steps;
    pts.push_back({m.at.x + r * std::cos(a), m.at.y + r * std::sin(a)});
  }
  return pts;
}

}  // namespace

namespace {

bool at_auxiliary(const Drawing& d, Point2 p) {
  return std::any_of(d.markers.begin(), d.markers.end(),
                     [&](const Marker& m) { return m.auxiliary && m.at.x == p.x && m.at.y == p.y; });
}

// The linkage's own box: patches, segments (an end at an auxiliary point, such as a line to Q_j,
// does not count: it is clipped by the view) and the markers that are not auxiliary.
Box core_box(const Drawing& d) {
  Box core;
  for (const auto& p : d.patches)
    for (const auto& q : p.points) core.add(q);
  for (const auto& s : d.segments)
    for (const Point2 e : {s.a, s.b})
      if (!at_auxiliary(d, e)) core.add(e);
  for (const auto& m : d.markers)
    if (!m.auxiliary) core.add(m.at);
  return core;
}

View with_margin(const Box& shown, double fraction) {
  View v;
  const double margin = fraction * std::max(shown.x1 - shown.x0, shown.y1 - shown.y0) + 1e-9;
  v.x0 = shown.x0 - margin, v.y0 = shown.y0 - margin, v.x1 = shown.x1 + margin, v.y1 = shown.y1 + margin;
  return v;
}

double extent(const View& v) { return std::max(v.x1 - v.x0, v.y1 - v.y0); }

}  // namespace

View compute_view(const Drawing& d) {
  Box core = core_box(d);
  if (core.empty()) core = Box{0, 0, 1, 1};
  const double span = std::max({core.x1 - core.x0, core.y1 - core.y0, 1e-9});
  Box limit{core.x0 - d.max_zoom_out * span, core.y0 - d.max_zoom_out * span, core.x1 + d.max_zoom_out * span,
            core.y1 + d.max_zoom_out * span};
  Box shown = core;
  std::vector<std::string> off_view;
  for (const auto& m : d.markers)
    if (m.auxiliary) {
      if (limit.contains(m.at))
        shown.add(m.at);
      else
        off_view.push_back(fmt::format("{} at ({:.6g}, {:.6g})", m.label, m.at.x, m.at.y));
    }
  View v = with_margin(shown, 0.08);
  v.off_view = std::move(off_view);
  return v;
}

std::optional<View> detail_view(const Drawing& d) {
  const Box linkage = core_box(d);
  if (linkage.empty() || std::max(linkage.x1 - linkage.x0, linkage.y1 - linkage.y0) <= 0) return std::nullopt;
  const View detail = with_margin(linkage, 0.12);
  if (extent(compute_view(d)) <= kDetailRatio * extent(detail)) return std::nullopt;
  return detail;
}

std::string label_tex(const std::string& label) {
  const auto [base, sub] = split_label(label);
  static const char* greek[] = {"alpha", "beta", "gamma", "omega", "phi", "lambda", "mu"};
  std::string b = latex_math_escape(base);
  for (const char* g : greek)
    if (base == g) b = std::string("\\") + g;
  if (sub.empty()) return b;
  return b + "_{" + latex_math_escape(sub, true) + "}";
}

namespace {

// The primitives of `d` seen through view `v` at `scale` pixels per unit, in the coordinates
// of a panel whose top left is (0, 0).
std::string svg_body(const Drawing& d, const View& v, double scale) {
  const auto X = [&](double x) { return (x - v.x0) * scale; };
  const auto Y = [&](double y) { return (v.y1 - y) * scale; };  // y up in the world
  std::string s;
  for (const auto& p : d.patches) {
    s += "<polygon points=\"";
    for (const auto& q : p.points) s += fmt::format("{:.2f},{:.2f} ", X(q.x), Y(q.y));
    s += fmt::format("\" fill=\"{}\" fill-opacity=\"0.35\" stroke=\"none\"/>\n", svg_escape(p.color));
  }
  for (const auto& g : d.segments) {
    s += fmt::format("<line x1=\"{:.2f}\" y1=\"{:.2f}\" x2=\"{:.2f}\" y2=\"{:.2f}\" stroke=\"{}\" "
                     "stroke-width=\"{}\"{}{}/>\n",
                     X(g.a.x), Y(g.a.y), X(g.b.x), Y(g.b.y), svg_escape(g.color), width_of(g.stroke), dash_of(g.stroke),
                     g.arrow ? " marker-end=\"url(#arrow)\"" : "");
    if (!g.label.empty())
      s += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" fill=\"{}\">{}</text>\n", X((g.a.x + g.b.x) / 2) + 4,
                       Y((g.a.y + g.b.y) / 2) - 4, svg_escape(g.color), svg_label(g.label));
  }
  for (const auto& m : d.angles) {
    const auto pts = arc_points(m, 22 / scale);
    s += "<polyline fill=\"none\" stroke=\"" + svg_escape(m.color) + "\" stroke-width=\"1.5\" points=\"";
    for (const auto& q : pts) s += fmt::format("{:.2f},{:.2f} ", X(q.x), Y(q.y));
    s += "\"/>\n";
    const Point2 mid = pts[pts.size() / 2];
    s += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" fill=\"{}\">{}</text>\n", X(mid.x) + 3, Y(mid.y) - 3,
                     svg_escape(m.color), svg_label(m.label));
  }
  // Markers at one place (a slider's two joints) have their labels stacked, not overprinted.
  std::vector<std::pair<Point2, int>> placed;
  for (const auto& m : d.markers) {
    if (!std::isfinite(m.at.x) || !std::isfinite(m.at.y)) continue;
    s += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{}\" fill=\"{}\" stroke=\"{}\" stroke-width=\"1.5\"/>\n",
                     X(m.at.x), Y(m.at.y), m.hollow ? 4.5 : 3, m.hollow ? "white" : svg_escape(m.color),
                     svg_escape(m.color));
    if (m.label.empty()) continue;
    int below = -1;
    for (auto& [p, n] : placed)
      if (std::abs(X(p.x) - X(m.at.x)) < 1 && std::abs(Y(p.y) - Y(m.at.y)) < 1) {
        below = n++;
        break;
      }
    if (below < 0) placed.push_back({m.at, 1}), below = 0;
    s += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" fill=\"{}\">{}</text>\n", X(m.at.x) + 6,
                     Y(m.at.y) - 6 - 14.0 * below, svg_escape(m.color), svg_label(m.label));
  }
  return s;
}

}  // namespace

std::string render_svg(const Drawing& d, double width_px) {
  const View v = compute_view(d);
  const std::optional<View> detail = detail_view(d);
  // The larger side of the view gets `width_px`: a tall figure does not run off the page.
  const double scale = width_px / extent(v);
  const double w1 = (v.x1 - v.x0) * scale, h1 = (v.y1 - v.y0) * scale;
  double w2 = 0, h2 = 0, scale2 = 0;
  if (detail) {
    // The linkage enlarged beside the whole: the same height as the whole, or its width.
    scale2 = std::min(h1 / (detail->y1 - detail->y0), width_px / (detail->x1 - detail->x0));
    w2 = (detail->x1 - detail->x0) * scale2, h2 = (detail->y1 - detail->y0) * scale2;
  }
  const double gap = detail ? 12 : 0, width = w1 + gap + w2, height = std::max(h1, h2);
  // Segments may reach far outside the view (lines to a distant Q_j): each panel (a nested svg)
  // clips them.
  std::string s = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 {:.2f} {:.2f}\" "
      "font-family=\"sans-serif\" font-size=\"13\">\n"
      "<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"10\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" "
      "orient=\"auto-start-reverse\"><path d=\"M 0 0 L 10 5 L 0 10 z\" fill=\"context-stroke\"/></marker></defs>\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      width, height, width, height);
  if (!detail) return s + svg_body(d, v, scale) + "</svg>\n";
  s += fmt::format("<svg x=\"0\" y=\"0\" width=\"{:.2f}\" height=\"{:.2f}\" viewBox=\"0 0 {:.2f} {:.2f}\">\n", w1, h1, w1, h1);
  s += svg_body(d, v, scale);
  s += "<text x=\"6\" y=\"16\" fill=\"#555555\">the whole construction</text>\n</svg>\n";
  s += fmt::format("<svg x=\"{:.2f}\" y=\"0\" width=\"{:.2f}\" height=\"{:.2f}\" viewBox=\"0 0 {:.2f} {:.2f}\">\n",
                   w1 + gap, w2, h2, w2, h2);
  s += svg_body(d, *detail, scale2);
  s += fmt::format("<rect x=\"0.5\" y=\"0.5\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"none\" stroke=\"#999999\"/>\n"
                   "<text x=\"6\" y=\"16\" fill=\"#555555\">the linkage enlarged ({:.3g}x)</text>\n</svg>\n",
                   w2 - 1, h2 - 1, scale2 / scale);
  return s + "</svg>\n";
}

namespace {

// One picture of `d` seen through view `v`, its larger side `width_cm`.
std::string latex_picture(const Drawing& d, const View& v, double width_cm) {
  // The geometry is one block of PDF path operators (\pdfliteral, built into pdfTeX: no
  // package needed), in big points relative to the picture's origin; labels are \put.
  const double scale = width_cm / 2.54 * 72 / std::max(v.x1 - v.x0, v.y1 - v.y0);
  const double width_bp = (v.x1 - v.x0) * scale;
  const double height_bp = (v.y1 - v.y0) * scale;
  const auto X = [&](double x) { return (x - v.x0) * scale; };
  const auto Y = [&](double y) { return (y - v.y0) * scale; };
  std::string lit = fmt::format("q 0 0 {:.2f} {:.2f} re W n ", width_bp, height_bp);  // clip to the view
  for (const auto& p : d.patches) {
    if (p.points.empty()) continue;
    lit += fmt::format("{} rg ", pdf_rgb(p.color));
    for (size_t k = 0; k < p.points.size(); ++k)
      lit += fmt::format("{:.2f} {:.2f} {} ", X(p.points[k].x), Y(p.points[k].y), k == 0 ? "m" : "l");
    lit += "h f ";
  }
  for (const auto& g : d.segments) {
    lit += fmt::format("{} RG {} w {} ", pdf_rgb(g.color), width_of(g.stroke) * 0.6,
                       g.stroke == Stroke::Dashed ? "[4 3] 0 d" : "[] 0 d");
    lit += fmt::format("{:.2f} {:.2f} m {:.2f} {:.2f} l S ", X(g.a.x), Y(g.a.y), X(g.b.x), Y(g.b.y));
    if (g.arrow) {
      const double dx = X(g.b.x) - X(g.a.x), dy = Y(g.b.y) - Y(g.a.y), len = std::hypot(dx, dy);
      if (len > 0) {
        const double ux = dx / len, uy = dy / len, h = 5;
        lit += fmt::format("{} rg [] 0 d {:.2f} {:.2f} m {:.2f} {:.2f} l {:.2f} {:.2f} l h f ", pdf_rgb(g.color),
                           X(g.b.x), Y(g.b.y), X(g.b.x) - h * ux - 0.5 * h * uy, Y(g.b.y) - h * uy + 0.5 * h * ux,
                           X(g.b.x) - h * ux + 0.5 * h * uy, Y(g.b.y) - h * uy - 0.5 * h * ux);
      }
    }
  }
  for (const auto& m : d.angles) {
    const auto pts = arc_points(m, 14 / scale);
    lit += fmt::format("{} RG 0.8 w [] 0 d ", pdf_rgb(m.color));
    for (size_t k = 0; k < pts.size(); ++k)
      lit += fmt::format("{:.2f} {:.2f} {} ", X(pts[k].x), Y(pts[k].y), k == 0 ? "m" : "l");
    lit += "S ";
  }
  for (const auto& m : d.markers) {
    if (!std::isfinite(m.at.x) || !std::isfinite(m.at.y)) continue;
    const double r = m.hollow ? 2.6 : 1.8, cx = X(m.at.x), cy = Y(m.at.y);
    // A circle as four Bezier quarter arcs (k = 0.5523 r).
    const double k = 0.5523 * r;
    lit += fmt::format(
        "{} RG {} rg 0.8 w [] 0 d {:.2f} {:.2f} m {:.2f} {:.2f} {:.2f} {:.2f} {:.2f} {:.2f} c {:.2f} {:.2f} {:.2f} "
        "{:.2f} {:.2f} {:.2f} c {:.2f} {:.2f} {:.2f} {:.2f} {:.2f} {:.2f} c {:.2f} {:.2f} {:.2f} {:.2f} {:.2f} {:.2f} "
        "c h B ",
        pdf_rgb(m.color), m.hollow ? "1 1 1" : pdf_rgb(m.color), cx + r, cy, cx + r, cy + k, cx + k, cy + r, cx, cy + r,
        cx - k, cy + r, cx - r, cy + k, cx - r, cy, cx - r, cy - k, cx - k, cy - r, cx, cy - r, cx + k, cy - r, cx + r,
        cy - k, cx + r, cy);
  }
  lit += "Q";
  std::string s = fmt::format("\\setlength{{\\unitlength}}{{1bp}}\n\\begin{{picture}}({:.2f},{:.2f})\n", width_bp, height_bp);
  s += "\\put(0,0){\\pdfliteral{" + lit + "}}\n";
  const auto put_label = [&](double x, double y, const std::string& label) {
    if (x < 0 || y < 0 || x > width_bp || y > height_bp) return;
    s += fmt::format("\\put({:.2f},{:.2f}){{\\footnotesize ${}$}}\n", x, y, label_tex(label));
  };
  for (const auto& m : d.markers)
    if (!m.label.empty() && std::isfinite(m.at.x)) put_label(X(m.at.x) + 3, Y(m.at.y) + 3, m.label);
  for (const auto& g : d.segments)
    if (!g.label.empty()) put_label(X((g.a.x + g.b.x) / 2) + 2, Y((g.a.y + g.b.y) / 2) + 2, g.label);
  for (const auto& m : d.angles) {
    const Point2 mid = arc_points(m, 14 / scale)[12];
    put_label(X(mid.x) + 2, Y(mid.y) + 2, m.label);
  }
  s += "\\end{picture}\n";
  return s;
}

}  // namespace

std::string render_latex_picture(const Drawing& d, double width_cm) {
  const View v = compute_view(d);
  const std::optional<View> detail = detail_view(d);
  if (!detail) return latex_picture(d, v, width_cm);
  // The whole and the linkage enlarged side by side, each on half the width.
  return latex_picture(d, v, width_cm * 0.6) + "\\quad\n" + latex_picture(d, *detail, width_cm * 0.6);
}

}  // namespace linkproof::report
