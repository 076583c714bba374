// A drawing to scale, in world coordinates (x right, y up, the linkage's own units), made of a
// few primitives, rendered to SVG (HTML and Markdown reports) or to a LaTeX picture (pdflatex,
// with pict2e for arbitrary slopes). One model, two renderers: a figure is computed once.
//
// The view is the bounding box of every primitive that is not marked `auxiliary`, widened to
// include auxiliary points (construction points such as Q_j) only while they lie within
// `max_zoom_out` times that box: a point far away (Q_j near infinity) does not shrink the
// linkage to a dot; it is listed in `off_view` with its coordinates instead. A line to such a
// point (an end at an auxiliary marker) does not widen the view either: the view clips it.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace linkproof::report {

struct Point2 {
  double x = 0, y = 0;
};

enum class Stroke { Solid, Dashed, Thin };

struct Segment {
  Point2 a, b;
  std::string color = "#222222";
  Stroke stroke = Stroke::Solid;
  bool arrow = false;  ///< arrow head at b (vectors of velocity and acceleration polygons)
  std::string label{};  ///< drawn at the middle, may be empty ({}: aggregates may leave it out)
};

struct Marker {
  Point2 at;
  std::string label;  ///< plain text, e.g. "K'_1" (renderers typeset the subscript)
  std::string color = "#222222";
  bool hollow = false;  ///< a joint (hollow circle) rather than a construction point (filled)
  bool auxiliary = false;
};

/// A closed polygon (a link with three or more joints), lightly filled.
struct Patch {
  std::vector<Point2> points;
  std::string color = "#cccccc";
};

/// An angle mark: an arc at `at` from direction `from` to direction `to` (counter-clockwise
/// when the angle is positive), with a label (e.g. "beta_1").
struct AngleMark {
  Point2 at, from, to;  ///< from/to are direction vectors
  std::string label;
  std::string color = "#aa3300";
};

struct Drawing {
  std::vector<Patch> patches;
  std::vector<Segment> segments;
  std::vector<AngleMark> angles;
  std::vector<Marker> markers;
  double max_zoom_out = 6;
  /// Filled by view(): auxiliary markers left out of the view ("Q_2 at (-8, 31)").
  std::vector<std::string> notes;
};

struct View {
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;  ///< world box
  std::vector<std::string> off_view;      ///< labels of auxiliary markers outside it
};

/// The world box shown (see the header comment), with a margin.
View compute_view(const Drawing& d);

/// The view is "much larger" than the linkage beyond this ratio of their larger sides.
inline constexpr double kDetailRatio = 4;

/// When construction points make the view much larger than the linkage itself (its patches,
/// its segments but for their ends at auxiliary points, its non-auxiliary markers), that box with a margin: render_svg draws it as a
/// second, enlarged panel beside the whole, so that the mechanism stays legible. nullopt
/// otherwise.
std::optional<View> detail_view(const Drawing& d);

/// The drawing as a standalone SVG document; the larger side of the view is `width_px` pixels.
/// With a detail_view, two panels side by side (each a nested svg that clips its lines): the
/// whole, and the linkage enlarged to the whole's height.
std::string render_svg(const Drawing& d, double width_px = 640);

/// The drawing as a LaTeX picture environment drawn by \pdfliteral (pdfTeX; no package needed);
/// the larger side of the view is `width_cm`. With a detail_view, two pictures side by side
/// (0.6 `width_cm` each): the whole and the linkage enlarged.
std::string render_latex_picture(const Drawing& d, double width_cm = 12);

/// "K'_1" -> TeX "K'_{1}", "beta_2" -> "\beta_{2}": labels of markers as TeX math. The label
/// splits at its first '_' into base and subscript; both are escaped by latex_math_escape
/// (report/escape.h), so a link or joint name shows as written and can start no command, end
/// no math and open no group ("A_B_C" -> "A_{B\_C}"); only the program's own one-letter
/// superscript at the end ("A_BA^t") stays one.
std::string label_tex(const std::string& label);

}  // namespace linkproof::report
