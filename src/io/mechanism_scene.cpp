#include "linkproof/io/mechanism_scene.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "linkproof/core/error.h"
#include "mechanism/joint_joining.h"
#include "joint_placement.h"
#include "quantity_text.h"
#include "scene_ask.h"
#include "yaml_document.h"
#include "geometry/zero_vector.h"
#include "mechanism/zero_length_driver.h"

namespace linkproof {

using namespace yaml_io;

namespace {

class MechanismReader {
  // A driven link of zero length (mechanism/zero_length_driver.h) drives no motion.
  void refuse_zero_length_drivers(const MechanismScene& scene) const {
    const Linkage& g = scene.linkage;
    std::vector<Vec2<Rational>> at;
    for (const LinkageJoint& j : g.joints()) at.push_back(j.at);
    if (const auto z = zero_length_driver(g, scene.inputs, at))
      fail(fmt::format("mechanism.inputs[{}].link", z->input),
           fmt::format("the driven link {} has zero length: its joints {} and {} are both at ({}, {}); a driven link "
                       "needs two joints at different points",
                       backticked(g.link_name(scene.inputs[z->input].index)), backticked(g.joint(z->first).name),
                       backticked(g.joint(z->second).name), format_rational(z->at.x), format_rational(z->at.y)));
  }

 public:
  explicit MechanismReader(std::string source) : source_(std::move(source)) {}

  MechanismScene read(const YAML::Node& doc) {
    if (!doc.IsMap()) fail("", "expected a map with the fields `name` and `mechanism`, got " + kind_of(doc));
    if (!doc["mechanism"] && doc["polygon"])
      fail("mechanism", "expected a mechanism scene (a top-level `mechanism:` key), got a polygon scene (checked by "
                        "`linkproof check`)");
    check_keys(doc, "", {"name", "description", "mechanism", "curvature", "joint_joining", "ask"});
    MechanismScene scene;
    scene.source = source_;
    const YAML::Node name = doc["name"];
    if (!name || !name.IsScalar() || name.Scalar().find_first_not_of(" \t\r\n") == std::string::npos)
      fail("name", "expected the scene's name, a non-empty string");
    scene.name = clean_text(name.Scalar());
    if (const YAML::Node d = doc["description"]; d && !d.IsScalar())
      fail("description", "expected a string (free text), got " + kind_of(d));
    const YAML::Node m = doc["mechanism"];
    if (!m) fail("mechanism", "missing required field `mechanism`");
    if (!m.IsMap()) fail("mechanism", "expected a map with ground, joints and inputs, got " + kind_of(m));
    check_keys(m, "mechanism.",
               {"ground", "links", "joints", "inputs", "points", "dimensions", "tolerance", "catalogue", "curvature",
                "joint_joining"});

    read_links(m);
    const int ground = link_index(m["ground"], "mechanism.ground", true);
    std::vector<LinkageJoint> joints = read_joints(m, scene.placement);
    // Links first named by joints are known now; the ground must be one of them.
    if (std::string problem = linkage_problem(links_, ground, joints); !problem.empty())
      fail("mechanism.joints", problem);
    scene.linkage = Linkage(links_, ground, std::move(joints));
    scene.inputs = read_inputs(m, scene.linkage, scene.placement);
    refuse_zero_length_drivers(scene);
    scene.points = read_points(m, scene.linkage);
    if (const YAML::Node t = m["tolerance"]) {
      scene.tolerance = read_exact_number(t, source_, "mechanism.tolerance", "the closure tolerance");
      if (cln::minusp(*scene.tolerance)) fail("mechanism.tolerance", "expected a tolerance >= 0");
    }
    read_dimensions(m, scene);
    // The second-order work: at the top level (as in docs/curvature.md) or inside `mechanism`.
    for (const char* key : {"curvature", "joint_joining"})
      if (doc[key] && m[key])
        fail(std::string("mechanism.") + key, std::string("`") + key + "` is given both at the top level and in `mechanism`");
    read_curvature(doc["curvature"] ? doc["curvature"] : m["curvature"], doc["curvature"] ? "curvature" : "mechanism.curvature",
                   scene);
    read_joint_joining(doc["joint_joining"] ? doc["joint_joining"] : m["joint_joining"],
                       doc["joint_joining"] ? "joint_joining" : "mechanism.joint_joining", scene);
    if (const YAML::Node c = m["catalogue"]) {
      if (!c.IsSequence()) fail("mechanism.catalogue", "expected a list of catalogue names, got " + kind_of(c));
      for (const auto& e : c) {
        if (!e.IsScalar()) fail("mechanism.catalogue", "expected catalogue names (strings), got " + kind_of(e));
        scene.catalogues.push_back(clean_text(e.Scalar()));
      }
    }
    if (const YAML::Node a = doc["ask"]) scene.ask = read_ask(a, scene);
    return scene;
  }

  // The mechanism's ask: rates and `links` name links, `points` name joints or tracer points.
  SceneAsk read_ask(const YAML::Node& node, const MechanismScene& scene) const {
    SceneAsk ask = read_scene_ask(node, source_);
    const Linkage& g = scene.linkage;
    const auto known_link = [&](const AskedName& n, const std::string& what) {
      if (!g.find_link(n.name))
        fail(n.field, fmt::format("{}: no link {} in this mechanism (links: {})", what, backticked(n.name),
                                  fmt::join(g.link_names(), ", ")));
    };
    for (const AskedRate& r : ask.rates) known_link(r.subject, r.text());
    for (const AskedName& n : ask.links) known_link(n, "links");
    for (const AskedName& n : ask.points) {
      const bool point = std::any_of(scene.points.begin(), scene.points.end(), [&](const auto& p) { return p.name == n.name; });
      if (!point && !g.find_joint(n.name))
        fail(n.field, "points: no joint or tracer point " + backticked(n.name) + " in this mechanism");
    }
    return ask;
  }

 private:
  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw InputError(source_, field, shorten(problem, kMaxProblem));
  }

  void check_keys(const YAML::Node& map, const std::string& prefix, std::initializer_list<const char*> allowed) const {
    std::set<std::string> seen;
    std::string expected;
    for (auto a : allowed) expected += (expected.empty() ? "" : ", ") + std::string(a);
    for (const auto& kv : map) {
      if (!kv.first.IsScalar()) fail(prefix, "a field name must be a plain string, got " + kind_of(kv.first));
      const std::string& k = kv.first.Scalar();
      if (std::none_of(allowed.begin(), allowed.end(), [&](const char* a) { return k == a; }))
        fail(prefix + shorten(k, kMaxQuoted), "unknown field " + backticked(k) + "; expected only: " + expected);
      if (!seen.insert(k).second) fail(prefix + k, "field " + backticked(k) + " is given twice");
    }
  }

  std::string name_of(const YAML::Node& n, const std::string& field, const std::string& what) const {
    if (!n) fail(field, "missing required field: " + what);
    if (!n.IsScalar() || n.Scalar().empty()) fail(field, "expected " + what + " (a non-empty string), got " + kind_of(n));
    return clean_text(n.Scalar());
  }

  void read_links(const YAML::Node& m) {
    const YAML::Node l = m["links"];
    if (!l) return;
    if (!l.IsSequence()) fail("mechanism.links", "expected a list of link names, got " + kind_of(l));
    for (size_t i = 0; i < l.size(); ++i) {
      const std::string name = name_of(l[i], fmt::format("mechanism.links[{}]", i), "a link name");
      if (std::find(links_.begin(), links_.end(), name) != links_.end())
        fail(fmt::format("mechanism.links[{}]", i), "link " + backticked(name) + " is listed twice");
      links_.push_back(name);
    }
    declared_ = true;
  }

  // The index of a named link; an undeclared name is added (no `links` list) or refused.
  int link_index(const YAML::Node& n, const std::string& field, bool add) {
    const std::string name = name_of(n, field, "a link name");
    const auto it = std::find(links_.begin(), links_.end(), name);
    if (it != links_.end()) return static_cast<int>(it - links_.begin());
    if (declared_ || !add)
      fail(field, "unknown link " + backticked(name) + (declared_ ? ": not in mechanism.links" : ": no joint connects it"));
    links_.push_back(name);
    return static_cast<int>(links_.size()) - 1;
  }

  Vec2<Rational> read_point(const YAML::Node& n, const std::string& field, const std::string& what) const {
    if (!n) fail(field, "missing required field: " + what + " [x, y]");
    if (!n.IsSequence() || n.size() != 2)
      fail(field, "expected " + what + " as a list of 2 numbers [x, y], got " +
                      (n.IsSequence() ? fmt::format("{} values", n.size()) : kind_of(n)));
    return {read_exact_number(n[0], source_, field + "[0]", "the x of " + what),
            read_exact_number(n[1], source_, field + "[1]", "the y of " + what)};
  }

  // The joint's name as a reference from another joint's placement.
  std::string joint_reference(const YAML::Node& n, const std::string& field) const {
    return name_of(n, field, "a joint's name");
  }

  // An exact length > 0.
  Rational read_length(const YAML::Node& n, const std::string& field, const std::string& what) const {
    const Rational l = read_exact_number(n, source_, field, what);
    if (!cln::plusp(l)) fail(field, "expected a length > 0 for " + what + ", got " + format_rational(l));
    return l;
  }

  // A number, or an angle or rate written with pi and a unit (quantity_text.h). Plain numbers,
  // booleans and NaN keep the exact-number reader and its messages.
  PiMultiple read_quantity(const YAML::Node& n, const std::string& field, const std::string& what,
                           QuantityKind kind) const {
    if (!n.IsDefined()) fail(field, "missing required field: " + quantity_kind_name(kind) + " for " + what);
    PiMultiple value;
    if (n.IsScalar() && looks_like_quantity_expression(n.Scalar()) && !is_reserved_word(n.Scalar())) {
      try {
        value = parse_quantity(n.Scalar(), kind);
      } catch (const std::invalid_argument& e) {
        fail(field, fmt::format("expected {} for {} ({}), got {}: {}", quantity_kind_name(kind), what,
                                quantity_examples(kind), backticked(n.Scalar()), e.what()));
      }
    } else {
      value = {read_exact_number(n, source_, field, what), 0};
    }
    if (kind == QuantityKind::Angle && !placement::is_angle_within_limit(value))
      fail(field, fmt::format("the angle {} is beyond {} rad in size (docs/limits.md)", backticked(n.Scalar()),
                              placement::kMaxAngleRadians));
    return value;
  }

  static bool is_reserved_word(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!s.empty() && (s.front() == '+' || s.front() == '-')) s.erase(0, 1);
    for (const char* w : {"true", "false", "yes", "no", "on", "off", "nan", ".nan", "inf", ".inf", "infinity"})
      if (s == w) return true;
    return false;
  }

  static std::string quantity_examples(QuantityKind kind) {
    switch (kind) {
      case QuantityKind::Angle: return "e.g. `30deg`, `pi/6`, `1.2rad`, or a number of radians";
      case QuantityKind::AngularVelocity: return "e.g. `1500rpm`, `-2000rpm`, `50*pi`, or a number of rad/s";
      case QuantityKind::AngularAcceleration: return "e.g. `100rpm/s`, `pi/2`, or a number of rad/s^2";
      case QuantityKind::Sliding: return "a number, possibly with `pi`, `*` and `/`";
    }
    return "";
  }

  // [J, L] of a dyad or slide: a joint's name and a length.
  std::pair<std::string, Rational> read_centre(const YAML::Node& n, const std::string& field, const std::string& what) const {
    if (!n || !n.IsSequence() || n.size() != 2)
      fail(field, "expected [joint, length] for " + what + ", got " +
                      (n && n.IsSequence() ? fmt::format("{} values", n.size()) : kind_of(n)));
    return {joint_reference(n[0], field + "[0]"), read_length(n[1], field + "[1]", "the length from that joint")};
  }

  int read_choice(const YAML::Node& n, const std::string& field, const char* plus, const char* minus,
                  const std::string& what) const {
    const std::string v = name_of(n, field, what);
    if (v == plus) return 1;
    if (v == minus) return -1;
    fail(field, fmt::format("expected `{}` or `{}` for {}, got {}", plus, minus, what, backticked(v)));
  }

  // The joint's placement: exactly one of `at` ([x, y] or a joint's name), `polar`, `dyad`, `slide`.
  placement::JointSpec read_placement(const YAML::Node& j, const std::string& f, const std::string& name) const {
    using Kind = placement::JointSpec::Kind;
    placement::JointSpec s;
    s.name = name;
    std::vector<std::string> given;
    for (const char* key : {"at", "polar", "dyad", "slide"})
      if (j[key]) given.push_back(key);
    if (given.empty())
      fail(f + ".at", "missing required field: the joint position [x, y] (or a placement from dimensions: `at: J`, "
                      "`polar`, `dyad` or `slide`; docs/mechanisms.md)");
    if (given.size() > 1)
      fail(f + "." + given[1], fmt::format("the joint position is given twice, by `{}` and by `{}`: give one",
                                           given[0], given[1]));
    const std::string key = given[0];
    const YAML::Node p = j[key];
    s.field = f + "." + key;
    if (key == "at") {
      if (p.IsScalar()) {
        s.kind = Kind::AtJoint;
        s.from = {{joint_reference(p, s.field), s.field}};
      } else {
        s.kind = Kind::Point;
        s.point = read_point(p, s.field, "the joint position");
      }
      return s;
    }
    if (!p.IsMap()) fail(s.field, fmt::format("expected a map for `{}` (docs/mechanisms.md), got {}", key, kind_of(p)));
    if (key == "polar") {
      check_keys(p, s.field + ".", {"from", "length", "angle"});
      s.kind = Kind::Polar;
      s.from = {{joint_reference(p["from"], s.field + ".from"), s.field + ".from"}};
      s.length = read_length(p["length"], s.field + ".length", "the distance from `from`");
      s.angle = read_quantity(p["angle"], s.field + ".angle", "the direction from `from`", QuantityKind::Angle);
      s.angle_text = clean_text(p["angle"].Scalar());
    } else if (key == "dyad") {
      check_keys(p, s.field + ".", {"from", "to", "side"});
      s.kind = Kind::Dyad;
      const auto [j1, l1] = read_centre(p["from"], s.field + ".from", "the first circle");
      const auto [j2, l2] = read_centre(p["to"], s.field + ".to", "the second circle");
      s.from = {{j1, s.field + ".from[0]"}, {j2, s.field + ".to[0]"}};
      s.length = l1, s.length2 = l2;
      s.side = read_choice(p["side"], s.field + ".side", "left", "right", "the side of the line from `from` to `to`");
    } else {
      check_keys(p, s.field + ".", {"line", "from", "pick"});
      s.kind = Kind::Slide;
      const YAML::Node line = p["line"];
      if (!line || !line.IsSequence() || line.size() != 2)
        fail(s.field + ".line", "expected [joint, angle] for the line, got " +
                                    (line && line.IsSequence() ? fmt::format("{} values", line.size()) : kind_of(line)));
      const std::string through = joint_reference(line[0], s.field + ".line[0]");
      s.angle = read_quantity(line[1], s.field + ".line[1]", "the line's direction", QuantityKind::Angle);
      s.angle_text = clean_text(line[1].Scalar());
      const auto [centre, l] = read_centre(p["from"], s.field + ".from", "the circle");
      s.from = {{through, s.field + ".line[0]"}, {centre, s.field + ".from[0]"}};
      s.length = l;
      s.side = read_choice(p["pick"], s.field + ".pick", "ahead", "behind",
                           "the intersection to take (farther along the line's direction, or nearer)");
    }
    return s;
  }

  // A prismatic axis: a direction [x, y], or an angle (an exactly unit rational direction).
  Vec2<Rational> read_axis(const YAML::Node& n, const std::string& field, const std::string& joint,
                           ScenePlacement& placement) const {
    if (!n || !n.IsScalar()) return read_point(n, field, "the guide direction");
    const PiMultiple angle = read_quantity(n, field, "the guide direction", QuantityKind::Angle);
    const placement::RationalisedDirection d = placement::rationalise_direction(angle);
    placement.axes.push_back({joint, "axis angle " + clean_text(n.Scalar()), d.exact, d.bound});
    return d.unit;
  }

  // The scene's size for rationalising positions: its largest given coordinate or length.
  static Rational scene_scale(const std::vector<placement::JointSpec>& specs) {
    Rational scale = 0;
    for (const auto& s : specs) {
      for (const Rational& v : {s.point.x, s.point.y, s.length, s.length2}) scale = cln::max(scale, cln::abs(v));
    }
    return cln::zerop(scale) ? Rational(1) : scale;
  }

  std::vector<LinkageJoint> read_joints(const YAML::Node& m, ScenePlacement& placement) {
    const YAML::Node js = m["joints"];
    if (!js) fail("mechanism.joints", "missing required field `joints`: the list of joints");
    if (!js.IsSequence() || js.size() == 0)
      fail("mechanism.joints", "expected a non-empty list of joints, got " + kind_of(js));
    if (js.size() > 2000) fail("mechanism.joints", fmt::format("expected at most 2000 joints, got {}", js.size()));
    std::vector<LinkageJoint> out;
    std::vector<placement::JointSpec> specs;
    // Slots (joint index, pin link) and axes given as {from: J} (joint index, J), resolved below.
    std::vector<std::pair<size_t, int>> slots;
    std::vector<std::pair<size_t, std::string>> axis_from;
    for (size_t i = 0; i < js.size(); ++i) {
      const std::string f = fmt::format("mechanism.joints[{}]", i);
      const YAML::Node j = js[i];
      if (!j.IsMap()) fail(f, "expected a map {name, type, links, at[, axis]}, got " + kind_of(j));
      check_keys(j, f + ".", {"name", "type", "links", "at", "polar", "dyad", "slide", "axis"});
      LinkageJoint joint;
      joint.name = name_of(j["name"], f + ".name", "the joint's name");
      for (const auto& o : out)
        if (o.name == joint.name) fail(f + ".name", "joint name " + backticked(joint.name) + " is used twice");
      const std::string type = name_of(j["type"], f + ".type", "the joint type (revolute, prismatic or slot)");
      const bool is_slot = type == "slot";
      if (type == "revolute") joint.type = JointType::Revolute;
      else if (type == "prismatic" || is_slot) joint.type = JointType::Prismatic;
      else fail(f + ".type", "expected `revolute` or `prismatic` (or `slot`: a pin in a straight slot), got " + backticked(type));
      const YAML::Node ls = j["links"];
      if (!ls || !ls.IsSequence() || ls.size() != 2)
        fail(f + ".links", "a joint connects exactly two links: expected a list of 2 link names, got " +
                               (ls && ls.IsSequence() ? fmt::format("{} names", ls.size()) : kind_of(ls)));
      for (int s = 0; s < 2; ++s) joint.links[s] = link_index(ls[s], fmt::format("{}.links[{}]", f, s), true);
      if (joint.links[0] == joint.links[1])
        fail(f + ".links", "joint " + backticked(joint.name) + " names the same link twice: a joint needs two different links");
      specs.push_back(read_placement(j, f, joint.name));
      if (is_slot) slots.push_back({i, joint.links[1]});
      if (joint.type == JointType::Prismatic) {
        const char* what = is_slot ? "the slot's direction" : "the guide direction of a prismatic pair";
        if (j["axis"] && j["axis"].IsMap()) {
          axis_from.push_back({i, read_axis_from(j["axis"], f + ".axis")});
        } else {
          joint.axis = read_axis(j["axis"], f + ".axis", joint.name, placement);
          if (is_zero_vector(joint.axis)) fail(f + ".axis", std::string("zero axis: ") + what + " must be non-zero");
        }
      } else if (j["axis"]) {
        fail(f + ".axis", "only a prismatic joint has an axis");
      }
      out.push_back(std::move(joint));
    }
    // Positions: given ones as read, the others constructed in the order their references allow.
    const placement::Placement placed = placement::place_joints(specs, scene_scale(specs), source_);
    static const std::map<placement::JointSpec::Kind, std::string> kind_names = {
        {placement::JointSpec::Kind::Point, "at"},     {placement::JointSpec::Kind::AtJoint, "at joint"},
        {placement::JointSpec::Kind::Polar, "polar"},  {placement::JointSpec::Kind::Dyad, "dyad"},
        {placement::JointSpec::Kind::Slide, "slide"}};
    for (size_t i = 0; i < out.size(); ++i) {
      const placement::PlacedJoint& p = placed.joints[i];
      out[i].at = p.at;
      placement.joints.push_back({out[i].name, kind_names.at(specs[i].kind), p.exact, p.bound});
    }
    // An axis {from: J}: the direction from joint J to this joint (a radial slot).
    for (const auto& entry : axis_from) {  // not a structured binding: clang 14 cannot capture one
      const size_t i = entry.first;
      const std::string& from = entry.second;
      const std::string f = fmt::format("mechanism.joints[{}].axis", i);
      const auto it = std::find_if(out.begin(), out.end(), [&](const LinkageJoint& o) { return o.name == from; });
      if (it == out.end()) fail(f + ".from", "unknown joint " + backticked(from));
      out[i].axis = out[i].at - it->at;
      placement.axes_from.push_back({out[i].name, from});
      if (is_zero_vector(out[i].axis))
        fail(f, fmt::format("zero axis: joint {} is at the joint {} itself ({}, {}), so it gives no direction",
                            backticked(from), backticked(out[i].name), format_rational(it->at.x), format_rational(it->at.y)));
    }
    add_slot_blocks(out, slots, placement);
    return out;
  }

  // `axis: {from: J}`: the name J.
  std::string read_axis_from(const YAML::Node& n, const std::string& field) const {
    check_keys(n, field + ".", {"from"});
    return joint_reference(n["from"], field + ".from");
  }

  // A slot P (links [guide, pin link]) is a prismatic pair between the guide and a block link
  // `P.block` plus a revolute pair `P.pin` between the block and the pin link, both at P's point
  // (docs/mechanisms.md, "Slots"). The block turns with the guide; P keeps the sliding rates.
  void add_slot_blocks(std::vector<LinkageJoint>& out, const std::vector<std::pair<size_t, int>>& slots,
                       ScenePlacement& placement) {
    for (const auto& [i, pin_link] : slots) {
      const std::string f = fmt::format("mechanism.joints[{}]", i);
      const std::string block = out[i].name + ".block", pin = out[i].name + ".pin";
      if (std::find(links_.begin(), links_.end(), block) != links_.end())
        fail(f + ".name", "slot " + backticked(out[i].name) + " needs the link name " + backticked(block) +
                              " for its block, but a link has that name");
      if (std::any_of(out.begin(), out.end(), [&](const LinkageJoint& o) { return o.name == pin; }))
        fail(f + ".name", "slot " + backticked(out[i].name) + " needs the joint name " + backticked(pin) +
                              " for its pin, but a joint has that name");
      links_.push_back(block);
      const int b = static_cast<int>(links_.size()) - 1;
      out[i].links[1] = b;
      LinkageJoint r;
      r.name = pin, r.type = JointType::Revolute, r.links[0] = b, r.links[1] = pin_link, r.at = out[i].at;
      out.push_back(std::move(r));
      const GivenValue given = placement.joints[i];
      placement.joints.push_back({pin, "at joint", given.exact, given.bound});
    }
  }

  // An input's rate: a number, or an expression with pi and a unit, rationalised when it is not a
  // rational number (recorded in `placement.rates`).
  Rational read_rate(const YAML::Node& n, const std::string& field, const std::string& what, QuantityKind kind,
                     ScenePlacement& placement) const {
    const PiMultiple q = read_quantity(n, field, what, kind);
    if (!n.IsScalar() || !looks_like_quantity_expression(n.Scalar())) return q.coefficient;
    const placement::RationalisedNumber r = placement::rationalise_number(q);
    placement.rates.push_back({field.substr(std::string("mechanism.").size()), clean_text(n.Scalar()), r.exact, r.bound});
    return r.value;
  }

  std::vector<MechanismInput> read_inputs(const YAML::Node& m, const Linkage& g, ScenePlacement& placement) {
    const YAML::Node in = m["inputs"];
    if (!in) fail("mechanism.inputs", "missing required field `inputs`: one per degree of freedom");
    if (!in.IsSequence()) fail("mechanism.inputs", "expected a list of inputs, got " + kind_of(in));
    std::vector<MechanismInput> out;
    for (size_t i = 0; i < in.size(); ++i) {
      const std::string f = fmt::format("mechanism.inputs[{}]", i);
      const YAML::Node n = in[i];
      if (!n.IsMap()) fail(f, "expected {link, omega, omega_dot} or {joint, v, a}, got " + kind_of(n));
      MechanismInput x;
      if (n["link"]) {
        check_keys(n, f + ".", {"link", "omega", "omega_dot"});
        x.kind = MechanismInput::Kind::Link;
        x.index = link_index(n["link"], f + ".link", false);
        if (x.index == g.ground()) fail(f + ".link", "an input on the ground link: its rates are 0 by definition");
        x.rate = read_rate(n["omega"], f + ".omega", "omega of the input link", QuantityKind::AngularVelocity, placement);
        x.rate_dot = read_rate(n["omega_dot"], f + ".omega_dot", "omega-dot of the input link",
                               QuantityKind::AngularAcceleration, placement);
      } else if (n["joint"]) {
        check_keys(n, f + ".", {"joint", "v", "a"});
        x.kind = MechanismInput::Kind::Slider;
        const std::string name = name_of(n["joint"], f + ".joint", "a joint name");
        const auto j = g.find_joint(name);
        if (!j) fail(f + ".joint", "unknown joint " + backticked(name));
        if (g.joint(*j).type != JointType::Prismatic)
          fail(f + ".joint", "joint " + backticked(name) + " is revolute: a slider input needs a prismatic joint");
        x.index = *j;
        x.rate = read_rate(n["v"], f + ".v", "the sliding velocity", QuantityKind::Sliding, placement);
        x.rate_dot = read_rate(n["a"], f + ".a", "the sliding acceleration", QuantityKind::Sliding, placement);
      } else {
        fail(f, "an input names a `link` (with omega, omega_dot) or a prismatic `joint` (with v, a)");
      }
      for (const auto& o : out)
        if (o.kind == x.kind && o.index == x.index) fail(f, "the same link or joint is driven twice");
      out.push_back(x);
    }
    return out;
  }

  // A point's name is its own: claims and the ask name joints and points alike, so a second
  // point or a joint of that name would be read in its place.
  std::vector<MechanismPoint> read_points(const YAML::Node& m, const Linkage& linkage) {
    std::vector<MechanismPoint> out;
    const YAML::Node ps = m["points"];
    if (!ps) return out;
    if (!ps.IsSequence()) fail("mechanism.points", "expected a list of points {name, link, at}, got " + kind_of(ps));
    for (size_t i = 0; i < ps.size(); ++i) {
      const std::string f = fmt::format("mechanism.points[{}]", i);
      if (!ps[i].IsMap()) fail(f, "expected a map {name, link, at}, got " + kind_of(ps[i]));
      check_keys(ps[i], f + ".", {"name", "link", "at"});
      MechanismPoint p;
      p.name = name_of(ps[i]["name"], f + ".name", "the point's name");
      for (int k = 0; k < linkage.joint_count(); ++k)
        if (linkage.joint(k).name == p.name)
          fail(f + ".name", backticked(p.name) + " is the name of a joint: a tracer point needs a name of its own");
      for (const MechanismPoint& q : out)
        if (q.name == p.name) fail(f + ".name", "the point " + backticked(p.name) + " is given twice");
      p.link = link_index(ps[i]["link"], f + ".link", false);
      p.at = read_point(ps[i]["at"], f + ".at", "the point's position");
      out.push_back(std::move(p));
    }
    return out;
  }

  // curvature: [{point, moving, fixed}]: a joint's or tracer point's name, two different links.
  void read_curvature(const YAML::Node& cs, const std::string& field, MechanismScene& scene) {
    if (!cs) return;
    if (!cs.IsSequence()) fail(field, "expected a list of {point, moving, fixed}, got " + kind_of(cs));
    const Linkage& g = scene.linkage;
    for (size_t i = 0; i < cs.size(); ++i) {
      const std::string f = fmt::format("{}[{}]", field, i);
      if (!cs[i].IsMap()) fail(f, "expected a map {point, moving, fixed}, got " + kind_of(cs[i]));
      check_keys(cs[i], f + ".", {"point", "moving", "fixed"});
      CurvatureRequest r;
      r.point = name_of(cs[i]["point"], f + ".point", "a joint or tracer point name");
      if (const auto j = g.find_joint(r.point)) {
        r.at = g.joint(*j).at;
      } else {
        const auto p = std::find_if(scene.points.begin(), scene.points.end(),
                                    [&](const MechanismPoint& q) { return q.name == r.point; });
        if (p == scene.points.end())
          fail(f + ".point", "unknown point " + backticked(r.point) + ": not a joint or a point of mechanism.points");
        r.at = p->at;
      }
      r.moving = link_index(cs[i]["moving"], f + ".moving", false);
      r.fixed = link_index(cs[i]["fixed"], f + ".fixed", false);
      if (r.moving == r.fixed) fail(f + ".fixed", "the moving and the fixed link are the same link: there is no relative motion");
      scene.curvature.push_back(std::move(r));
    }
  }

  // joint_joining: [{link, bars: [b1, b2], order: 1|2}].
  void read_joint_joining(const YAML::Node& js, const std::string& field, MechanismScene& scene) {
    if (!js) return;
    if (!js.IsSequence()) fail(field, "expected a list of {link, bars, order}, got " + kind_of(js));
    const Linkage& g = scene.linkage;
    for (size_t i = 0; i < js.size(); ++i) {
      const std::string f = fmt::format("{}[{}]", field, i);
      if (!js[i].IsMap()) fail(f, "expected a map {link, bars: [b1, b2], order: 1 or 2}, got " + kind_of(js[i]));
      check_keys(js[i], f + ".", {"link", "bars", "order"});
      JointJoiningRequest r;
      r.link = link_index(js[i]["link"], f + ".link", false);
      if (const YAML::Node o = js[i]["order"]) {
        const Rational order = read_exact_number(o, source_, f + ".order", "the order (1 or 2)");
        if (order != 1 && order != 2) fail(f + ".order", "expected 1 (first order) or 2 (second order), got " + format_rational(order));
        r.order = order == 1 ? 1 : 2;
      }
      const YAML::Node bars = js[i]["bars"];
      if (!bars || !bars.IsSequence() || bars.size() != 2)
        fail(f + ".bars", "expected a list of 2 bar (link) names, got " +
                              (bars && bars.IsSequence() ? fmt::format("{} names", bars.size()) : kind_of(bars)));
      for (int b = 0; b < 2; ++b) {
        const std::string bf = fmt::format("{}.bars[{}]", f, b);
        r.bars[b] = link_index(bars[b], bf, false);
        if (std::string p = bar_problem(g, r.link, r.bars[b]); !p.empty()) fail(bf, p);
        for (const MechanismInput& in : scene.inputs)
          if (in.kind == MechanismInput::Kind::Link && in.index == r.bars[b])
            fail(bf, "bar " + backticked(g.link_name(r.bars[b])) + " is the driver: joint-joining replaces it, so drive "
                     "another link");
      }
      if (r.bars[0] == r.bars[1]) fail(f + ".bars", "the two bars are the same link");
      scene.joint_joining.push_back(r);
    }
  }

  void read_dimensions(const YAML::Node& m, MechanismScene& scene) {
    const YAML::Node ds = m["dimensions"];
    if (!ds) return;
    if (!ds.IsSequence()) fail("mechanism.dimensions", "expected a list {joints: [A, B], length: L}, got " + kind_of(ds));
    const Linkage& g = scene.linkage;
    for (size_t i = 0; i < ds.size(); ++i) {
      const std::string f = fmt::format("mechanism.dimensions[{}]", i);
      const YAML::Node d = ds[i];
      if (!d.IsMap()) fail(f, "expected a map {joints: [A, B], length: L}, got " + kind_of(d));
      check_keys(d, f + ".", {"joints", "length"});
      const YAML::Node js = d["joints"];
      if (!js || !js.IsSequence() || js.size() != 2) fail(f + ".joints", "expected a list of 2 joint names");
      LinkDimension dim;
      int idx[2];
      for (int s = 0; s < 2; ++s) {
        const std::string name = name_of(js[s], fmt::format("{}.joints[{}]", f, s), "a joint name");
        const auto j = g.find_joint(name);
        if (!j) fail(fmt::format("{}.joints[{}]", f, s), "unknown joint " + backticked(name));
        idx[s] = *j;
      }
      dim.joint_a = idx[0], dim.joint_b = idx[1];
      const auto& ja = g.joint(idx[0]);
      const auto& jb = g.joint(idx[1]);
      const bool share = std::any_of(std::begin(ja.links), std::end(ja.links),
                                     [&](int l) { return l == jb.links[0] || l == jb.links[1]; });
      if (!share || idx[0] == idx[1]) fail(f + ".joints", "a dimension joins two different joints of one link");
      dim.length = read_exact_number(d["length"], source_, f + ".length", "the length");
      if (!cln::plusp(dim.length)) fail(f + ".length", "expected a length > 0");
      const Rational d2 = norm2(jb.at - ja.at);
      const double actual = std::sqrt(cln::double_approx(d2));
      const double residual = std::abs(actual - cln::double_approx(dim.length));
      scene.dimension_residual = std::max(scene.dimension_residual, residual);
      // A rationalised joint is within `bound` of its dimensioned position in each coordinate, so
      // |AB| may differ from the dimensioned distance by sqrt(2) (bound_A + bound_B) <= slack.
      const auto& given = scene.placement.joints;
      const Rational slack = given.empty() ? Rational(0)
                                           : 3 * (given[static_cast<size_t>(idx[0])].bound +
                                                  given[static_cast<size_t>(idx[1])].bound) / 2;
      bool ok;
      if (!scene.tolerance && cln::zerop(slack)) {
        ok = d2 == dim.length * dim.length;
      } else {
        const Rational allowed = scene.tolerance.value_or(0) + slack;
        const Rational lo = cln::max(Rational(0), dim.length - allowed), hi = dim.length + allowed;
        ok = lo * lo <= d2 && d2 <= hi * hi;
      }
      if (!ok)
        fail(f, fmt::format("the linkage does not close at the given positions: |{}{}| = {:.6g} but the declared "
                            "length is {} ({}{}); move the joints or state a `tolerance`",
                            ja.name, jb.name, actual, format_rational(dim.length),
                            scene.tolerance ? "tolerance " + format_rational(*scene.tolerance) : "exact input: no tolerance",
                            cln::zerop(slack) ? "" : ", plus the rationalisation of the positions"));
      scene.dimensions.push_back(dim);
    }
  }

  std::string source_;
  std::vector<std::string> links_;
  bool declared_ = false;
};

}  // namespace

bool is_mechanism_scene_text(const std::string& yaml_text) {
  try {
    const YAML::Node doc = parse_single_document(yaml_text, "", "");
    return doc.IsMap() && doc["mechanism"];
  } catch (const std::exception&) {
    return false;
  }
}

std::string read_scene_text(const std::string& path) { return read_scene_file(path); }

MechanismScene parse_mechanism_scene(const std::string& yaml_text, const std::string& source) {
  const YAML::Node doc = parse_single_document(
      yaml_text, source, "empty document: expected a map with the fields `name` and `mechanism`");
  try {
    return MechanismReader(source).read(doc);
  } catch (const YAML::Exception& e) {
    throw InputError(source, "", std::string("cannot read the YAML: ") + e.what());
  }
}

MechanismScene load_mechanism_scene(const std::string& path) {
  return parse_mechanism_scene(read_scene_file(path), path);
}

}  // namespace linkproof
