#include "report/mechanism_document.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "mechanism/fourbar_polygon.h"
#include "report/number_rich.h"
#include "report/number_text.h"
#include "report/polygon_document.h"
#include "report/slot_rows.h"
#include "svg_plot.h"

namespace linkproof::report {

namespace {

Point2 to_point(const Vec2<Rational>& p) { return {cln::double_approx(p.x), cln::double_approx(p.y)}; }


// The joints of link `k` (positions), ordered by angle around their centroid, so that a plate
// with three or more joints is drawn as a simple polygon.
std::vector<Point2> link_outline(const Linkage& g, int k) {
  std::vector<Point2> pts;
  for (const auto& j : g.joints())
    if (j.links[0] == k || j.links[1] == k) {
      const Point2 p = to_point(j.at);
      const bool seen = std::any_of(pts.begin(), pts.end(), [&](const Point2& q) {
        return std::abs(q.x - p.x) + std::abs(q.y - p.y) < 1e-12;
      });
      if (!seen) pts.push_back(p);
    }
  Point2 c{0, 0};
  for (const auto& p : pts) c.x += p.x / static_cast<double>(pts.size()), c.y += p.y / static_cast<double>(pts.size());
  std::sort(pts.begin(), pts.end(), [&](const Point2& a, const Point2& b) {
    return std::atan2(a.y - c.y, a.x - c.x) < std::atan2(b.y - c.y, b.x - c.x);
  });
  return pts;
}

// The values of a link's rates, "ω = …, ω̇ = …", for the headline.
Rich link_rates_rich(const std::string& name, const ResultNumber& omega, const ResultNumber& omega_dot) {
  Rich r = plain(name + ": ");
  r.push_back(math("\\omega ="));
  r.push_back(text(" "));
  for (const Span& x : number_rich(omega)) r.push_back(x);
  r.push_back(text(", "));
  r.push_back(math("\\dot\\omega ="));
  r.push_back(text(" "));
  for (const Span& x : number_rich(omega_dot)) r.push_back(x);
  return r;
}

// The summary opens with what a reader came for: the linkage drawn large beside the headline
// (the asked values, the mobility, the claims at a glance).
Section summary_section(const MechanismScene& scene, const MechanismCheck& check) {
  Section s{"summary", "Summary", {}, {}};
  s.blocks.push_back(figure_block({scene.name + "-linkage",
                                   "The linkage to scale: links as bars (two joints) or plates (three or more), "
                                   "joints as circles, sliders on their guides (dashed), tracer points filled.",
                                   mechanism_drawing(scene)}));
  std::vector<Rich> headline;
  if (check.ask)
    for (size_t k = 0; k < check.link_names.size() && k < check.omega.size(); ++k)
      headline.push_back(link_rates_rich(check.link_names[k], check.omega[k], check.omega_dot[k]));
  // A slot is one joint to the reader: its block link and pin joint are not counted.
  const int slots = static_cast<int>(check.slots.size());
  const int shown_links = scene.linkage.link_count() - slots, shown_joints = scene.linkage.joint_count() - slots;
  headline.push_back(plain(fmt::format("mobility {}: {} links, {} joints, {} independent loop{}", check.mobility,
                                       shown_links, shown_joints, check.loops, check.loops == 1 ? "" : "s")));
  for (Rich& r : claims_at_a_glance(check.claims)) headline.push_back(std::move(r));
  s.blocks.push_back(headline_block(std::move(headline)));
  int as_expected = 0;
  for (const auto& c : check.claims) as_expected += c.is_as_expected() ? 1 : 0;
  s.blocks.push_back(paragraph(plain(fmt::format(
      "Scene {} ({}): {} links, {} joints, {} independent loops; mobility {} (Gruebler {}), velocity-system rank {}, "
      "condition number {:.3g}. The motion is the exact solution of the differentiated loop closures; {} of {} "
      "claims as expected.",
      scene.name, scene.source, shown_links, shown_joints, check.loops, check.mobility,
      check.grubler, check.rank, check.condition, as_expected, check.claims.size()))));
  if (check.ask) {
    std::string asked, links;
    for (const auto& item : check.ask->describe()) asked += (asked.empty() ? "" : "; ") + item;
    for (const auto& l : check.computed_links) links += (links.empty() ? "" : ", ") + l;
    s.blocks.push_back(paragraph(plain(fmt::format(
        "The scene asks for {}. Only that was computed, on the smallest determined sub-mechanism found that "
        "contains it: links {} ({} of {} links, {} of {} loops; mobility, rank and condition above are its own). "
        "Sections of what was not needed are left out.",
        asked, links, check.computed_links.size(), check.all_links, check.loops, check.all_loops))));
  }
  if (!check.claims.empty()) s.blocks.push_back(table_block(claim_summary_table(check.claims, Arithmetic::Exact)));
  if (!check.not_applicable.empty()) {
    std::string na;
    for (const auto& id : check.not_applicable) na += (na.empty() ? "" : ", ") + id;
    s.blocks.push_back(paragraph(plain("Not applicable to this mechanism: " + na + ".")));
  }
  return s;
}

// The linkage with the velocity (or acceleration) of every joint and point as an arrow from it,
// all to one scale: the longest arrow is a third of the linkage's extent. `scale` receives the
// drawing's length per unit of velocity (acceleration); 0 where every vector is zero.
Drawing vector_drawing(const MechanismScene& scene, const MechanismCheck& check, bool acceleration, double& scale) {
  Drawing d = mechanism_drawing(scene);
  const View v = compute_view(d);
  const double extent = std::max(v.x1 - v.x0, v.y1 - v.y0);
  double longest = 0;
  const auto vec = [&](const MechanismCheck::PointMotion& p) {
    const auto& x = acceleration ? p.a : p.v;
    return Point2{to_double(x[0]), to_double(x[1])};
  };
  for (const auto* list : {&check.joints, &check.points})
    for (const auto& p : *list) {
      const Point2 w = vec(p);
      if (std::isfinite(w.x) && std::isfinite(w.y)) longest = std::max(longest, std::hypot(w.x, w.y));
    }
  scale = longest > 0 ? extent / 3 / longest : 0;
  std::map<std::string, Point2> at;
  for (const auto& m : d.markers) at.emplace(m.label, m.at);
  const std::string colour = acceleration ? "#b8005c" : "#0050b8";
  for (const auto* list : {&check.joints, &check.points})
    for (const auto& p : *list) {
      const auto it = at.find(p.name);
      const Point2 w = vec(p);
      if (it == at.end() || scale == 0 || !std::isfinite(w.x) || !std::isfinite(w.y) || std::hypot(w.x, w.y) == 0)
        continue;
      const Point2 from = it->second;
      d.segments.push_back({from, {from.x + scale * w.x, from.y + scale * w.y}, colour, Stroke::Solid, true, ""});
    }
  return d;
}

Section mechanism_section(const MechanismScene& scene, const MechanismCheck& check) {
  Section s{"mechanism", "Mechanism", {}, {}};
  if (!check.ask) {
    for (const bool acceleration : {false, true}) {
      double scale = 0;
      Drawing d = vector_drawing(scene, check, acceleration, scale);
      if (scale == 0) continue;
      s.blocks.push_back(figure_block(
          {scene.name + (acceleration ? "-accelerations" : "-velocities"),
           fmt::format("{} of the joints and points to scale: an arrow of the drawing's unit length is {:.4g} units "
                       "of {} (the longest arrow is a third of the drawing).",
                       acceleration ? "Accelerations" : "Velocities", 1 / scale,
                       acceleration ? "acceleration" : "velocity"),
           std::move(d)}));
    }
  }
  Table links{{plain("link"), tex("\\omega"), tex("\\dot\\omega")}, {}};
  for (size_t k = 0; k < check.link_names.size() && k < check.omega.size(); ++k)
    if (!is_hidden_slot_part(check, check.link_names[k]))  // a slot's block turns with the slotted link
      links.rows.push_back(
        {plain(check.link_names[k] + (check.link_names[k] == scene.linkage.link_name(scene.linkage.ground()) ? " (ground)" : "")),
         number_rich(check.omega[k]), number_rich(check.omega_dot[k])});
  if (!links.rows.empty()) {
    s.blocks.push_back(paragraph(plain(std::string("Angular velocity and acceleration of ") +
                                       (check.ask ? "the asked links" : "every link") + " relative to the ground (exact):")));
    s.blocks.push_back(table_block(std::move(links)));
  }
  Table pts{{plain("joint / point"), plain("velocity"), plain("acceleration"), plain("sliding rate, acceleration")}, {}};
  const auto pair = [](const ResultNumber& x, const ResultNumber& y) {
    Rich r = plain("(");
    for (const Span& a : number_rich(x)) r.push_back(a);
    r.push_back(text(", "));
    for (const Span& b : number_rich(y)) r.push_back(b);
    r.push_back(text(")"));
    return r;
  };
  bool sliding = false;
  const auto add = [&](const MechanismCheck::PointMotion& p) {
    Rich slide;
    if (p.slide) {
      sliding = true;
      slide = number_rich(*p.slide);
      slide.push_back(text(", "));
      for (const Span& b : number_rich(*p.slide_dot)) slide.push_back(b);
    }
    const MechanismCheck::Slot* slot = slot_of_joint(check, p.name);
    pts.rows.push_back({plain(slot ? p.name + " (" + slot_description(*slot) + ")" : p.name), pair(p.v[0], p.v[1]),
                        pair(p.a[0], p.a[1]), std::move(slide)});
  };
  for (const auto& p : check.joints)
    if (!is_hidden_slot_part(check, p.name)) add(p);  // a slot's pin: the slot's own point
  for (const auto& p : check.points) add(p);
  if (!sliding) {  // no prismatic joint: no empty column
    pts.header.pop_back();
    for (auto& row : pts.rows) row.pop_back();
  }
  if (!pts.rows.empty() || !check.ask) s.blocks.push_back(table_block(std::move(pts)));
  // Each slot as one joint: its sliding rates (above) and its Coriolis term.
  for (const auto& p : check.joints) {
    const MechanismCheck::Slot* slot = slot_of_joint(check, p.name);
    if (!slot || !p.sliding || !p.slide) continue;
    Rich r = plain(fmt::format("Slot {}: a {} (one joint; solved as a prismatic pair with a block that turns with {}). "
                               "The pin slides along u = ",
                               p.name, slot_description(*slot), slot->slotted));
    for (const Span& x : pair(ResultNumber(p.sliding->axis.x), ResultNumber(p.sliding->axis.y))) r.push_back(x);
    r.push_back(text(" at "));
    r.push_back(math("\\dot\\sigma ="));
    r.push_back(text(" "));
    for (const Span& x : number_rich(*p.slide)) r.push_back(x);
    r.push_back(text(", "));
    r.push_back(math("\\ddot\\sigma ="));
    r.push_back(text(" "));
    for (const Span& x : number_rich(*p.slide_dot)) r.push_back(x);
    r.push_back(text(" per unit of u; its Coriolis acceleration "));
    r.push_back(math("2\\,\\omega\\,J\\,v_{\\mathrm{rel}}"));
    r.push_back(text(", with "));
    r.push_back(math("\\omega"));
    r.push_back(text(" that of " + slot->slotted + ", is "));
    for (const Span& x : pair(p.sliding->coriolis[0], p.sliding->coriolis[1])) r.push_back(x);
    r.push_back(text("."));
    s.blocks.push_back(paragraph(std::move(r)));
  }
  return s;
}

// A plan (velocity or acceleration): every joint's vector drawn as a point from the origin o,
// each link's image joining the images of its joints.
Drawing plan_drawing(const MechanismScene& scene, const MechanismCheck& check, bool acceleration) {
  const Linkage& g = scene.linkage;
  std::map<std::string, Point2> image;
  for (const auto& p : check.joints) {
    const auto& v = acceleration ? p.a : p.v;
    image[p.name] = {to_double(v[0]), to_double(v[1])};
  }
  Drawing d;
  d.max_zoom_out = 1;
  const Point2 origin{0, 0};
  for (int k = 0; k < g.link_count(); ++k) {
    if (k == g.ground()) continue;
    std::vector<Point2> pts;
    for (const auto& j : g.joints())
      if ((j.links[0] == k || j.links[1] == k) && j.type == JointType::Revolute && image.count(j.name))
        pts.push_back(image[j.name]);
    for (size_t a = 0; a + 1 < pts.size(); ++a)
      for (size_t b = a + 1; b < pts.size(); ++b)
        d.segments.push_back({pts[a], pts[b], palette_color(static_cast<size_t>(k)), Stroke::Thin, false, ""});
  }
  // In the scene's joint order, not the map's name order: the drawing must not depend on how
  // names sort (a renamed joint would otherwise move in the SVG).
  for (const auto& j : check.joints) {
    if (is_hidden_slot_part(check, j.name)) continue;  // a slot's pin: the image of the slot P
    const Point2 p = image[j.name];
    d.segments.push_back({origin, p, "#555555", Stroke::Solid, true, ""});
    d.markers.push_back({p, j.name, "#222222", false, false});
  }
  d.markers.push_back({origin, "o", "#000000", true, false});
  return d;
}

// The four-bar's acceleration polygon head to tail (conventions §B), in the order of the course notes'
// rearranged equation A_A^n + A_A^t + A_BA^n - A_B^n + A_BA^t - A_B^t = 0.
std::optional<Drawing> fourbar_polygon_drawing(const MechanismScene& scene) {
  const auto roles = identify_fourbar(scene.linkage, scene.inputs);
  if (!roles) return std::nullopt;
  const Linkage& g = scene.linkage;
  try {
    const auto p = construct_fourbar_polygon(g.joint(roles->O2).at, g.joint(roles->A).at, g.joint(roles->B).at,
                                             g.joint(roles->O4).at, scene.inputs[0].rate, scene.inputs[0].rate_dot);
    Drawing d;
    d.max_zoom_out = 1;
    const std::pair<const char*, Vec2<Rational>> chain[] = {{"A_A^n", p.A_A_n},   {"A_A^t", p.A_A_t},
                                                            {"A_BA^n", p.A_BA_n}, {"-A_B^n", -p.A_B_n},
                                                            {"A_BA^t", p.A_BA_t}, {"-A_B^t", -p.A_B_t}};
    Vec2<Rational> at{Rational(0), Rational(0)};
    size_t k = 0;
    for (const auto& [label, v] : chain) {
      const Vec2<Rational> next = at + v;
      d.segments.push_back({to_point(at), to_point(next), palette_color(k++), Stroke::Solid, true, label});
      at = next;
    }
    d.segments.push_back({{0, 0}, to_point(p.A_A), "#888888", Stroke::Dashed, false, "A_A"});
    d.markers.push_back({{0, 0}, "O_A", "#000000", true, false});
    return d;
  } catch (const UndefinedQuantity&) {
    return std::nullopt;
  }
}

Section plans_section(const MechanismScene& scene, const MechanismCheck& check) {
  Section s{"plans", "Velocity and acceleration plans", {}, {}};
  s.blocks.push_back(figure_block({scene.name + "-velocity-plan",
                                   "Velocity plan: the velocity of every joint drawn from o (to its own scale); the "
                                   "image of each link joins its joints' images.",
                                   plan_drawing(scene, check, false)}));
  s.blocks.push_back(figure_block({scene.name + "-acceleration-plan", "Acceleration plan, drawn the same way.",
                                   plan_drawing(scene, check, true)}));
  if (auto fb = fourbar_polygon_drawing(scene))
    s.blocks.push_back(figure_block({scene.name + "-acceleration-polygon",
                                     "The four-bar's acceleration polygon as the course notes draw it (docs/conventions.md §B): from the "
                                     "acceleration origin O_A, head to tail, A_A^n, A_A^t, A_BA^n, -A_B^n, then the "
                                     "tangential A_BA^t and -A_B^t close it; the dashed vector is A_A.",
                                     *fb,
                                     {text("The four-bar's acceleration polygon as the course notes draw it "
                                           "(docs/conventions.md §B): from the acceleration origin "),
                                      math("O_A"), text(", head to tail, "), math("A_A^n, A_A^t, A_{BA}^n, -A_B^n"),
                                      text(", then the tangential "), math("A_{BA}^t"), text(" and "), math("-A_B^t"),
                                      text(" close it; the dashed vector is "), math("A_A"), text(".")}}));
  return s;
}

Section tables_section(const MechanismCheck& check) {
  Section s{"tables", "Catalogue tables", {}, {}};
  for (const auto& t : check.tables) {
    Table out{{plain("quantity"), plain("value (exact)")}, {}};
    for (const auto& [k, v] : t.rows) out.rows.push_back({plain(k), value_rich(v)});
    Section sub{"table-" + t.title, t.title, {}, {}};
    sub.blocks.push_back(table_block(std::move(out)));
    s.subsections.push_back(std::move(sub));
  }
  return s;
}

}  // namespace

Drawing mechanism_drawing(const MechanismScene& scene) {
  const Linkage& g = scene.linkage;
  Drawing d;
  for (int k = 0; k < g.link_count(); ++k) {
    const std::vector<Point2> pts = link_outline(g, k);
    const std::string col = k == g.ground() ? "#888888" : palette_color(static_cast<size_t>(k));
    if (k == g.ground()) continue;  // the frame is shown by its pivots, not as a body
    if (pts.size() >= 3) d.patches.push_back({pts, col});
    for (size_t a = 0; a < pts.size(); ++a) {
      if (pts.size() == 2 && a == 1) break;
      Segment seg{pts[a], pts[(a + 1) % pts.size()], col, Stroke::Solid, false, ""};
      // A link whose joints coincide (a slider block) is named by its joints, not over them.
      if (a == 0 && std::hypot(seg.a.x - seg.b.x, seg.a.y - seg.b.y) > 1e-9) seg.label = g.link_name(k);
      d.segments.push_back(seg);
    }
  }
  for (const auto& j : g.joints()) {
    const Point2 p = to_point(j.at);
    if (j.type == JointType::Prismatic) {
      const double len = std::hypot(cln::double_approx(j.axis.x), cln::double_approx(j.axis.y));
      const double ux = cln::double_approx(j.axis.x) / len, uy = cln::double_approx(j.axis.y) / len;
      // The guide: the line through the joint along its axis, 15 % of the drawing's extent each way.
      const View v = compute_view(d);
      const double r = 0.15 * std::max(v.x1 - v.x0, v.y1 - v.y0);
      // In two halves, the label on the far one: not on top of the joint's own label.
      d.segments.push_back({{p.x - r * ux, p.y - r * uy}, p, "#555555", Stroke::Dashed, false, ""});
      d.segments.push_back({p, {p.x + r * ux, p.y + r * uy}, "#555555", Stroke::Dashed, false, "guide " + j.name});
    }
    // A slot's pin joint P.pin lies on the slot P with its block P.block (io/mechanism_scene.h,
    // which refuses those names otherwise): the slot is drawn as P alone.
    if (is_slot_pin_joint(g, j.name)) continue;
    const bool grounded = j.links[0] == g.ground() || j.links[1] == g.ground();
    d.markers.push_back({p, j.name, grounded ? "#000000" : "#333333", true, false});
  }
  for (const auto& pt : scene.points) d.markers.push_back({to_point(pt.at), pt.name, "#aa0000", false, false});
  return d;
}

Document build_mechanism_document(const MechanismScene& scene, const MechanismCheck& check,
                                  const MechanismReportOptions& options) {
  Document d;
  d.title = "Mechanism report: " + scene.name;
  d.subtitle = "exact kinematics of a planar linkage; linkproof";
  d.sections.push_back(summary_section(scene, check));
  d.sections.push_back(mechanism_section(scene, check));
  if (options.plans && !check.ask) d.sections.push_back(plans_section(scene, check));  // plans need every joint
  if (!check.tables.empty()) d.sections.push_back(tables_section(check));
  Section terms = terms_section(check.claims);
  if (!terms.subsections.empty()) d.sections.push_back(std::move(terms));
  Section errata = errata_section(check.claims, options.scene_text);
  if (!errata.subsections.empty()) d.sections.push_back(std::move(errata));
  return d;
}

}  // namespace linkproof::report
