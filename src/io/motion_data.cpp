#include "io/motion_data.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cln/integer.h>
#include <cln/integer_io.h>
#include <cln/rational.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "linkproof/core/error.h"
#include "core/scalar.h"
#include "yaml_document.h"

namespace linkproof {

namespace {

double one_ulp(double magnitude) {
  return std::nextafter(magnitude, std::numeric_limits<double>::infinity()) - magnitude;
}

double digits_rule(long significant, long last_digit_exponent, const Rational& value, double scale) {
  double u = 0.5 * std::pow(10.0, static_cast<double>(last_digit_exponent));
  if (significant >= 16) u = std::max(u, one_ulp(std::max(std::abs(ScalarTraits<double>::from_rational(value)), scale)));
  return u;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) {
    const auto b = cell.find_first_not_of(" \t\r");
    const auto e = cell.find_last_not_of(" \t\r");
    out.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
  }
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

/// What a column holds.
struct Column {
  enum Kind { Label, Carried, X, Y, Omega, Alpha, SlideV, SlideA } kind = Label;
  int index = 0;  ///< joint or link
  std::string name;
};

class DataReader {
 public:
  DataReader(std::string source, const MechanismScene& scene)
      : source_(std::move(source)), scene_(scene), allowed_(allowed_columns()) {}

  MotionData read(const std::string& text) {
    MotionData data;
    data.source = source_;
    std::istringstream in(text);
    std::string line;
    int number = 0;
    bool header = false;
    while (std::getline(in, line)) {
      ++number;
      if (line.find_first_not_of(" \t\r") == std::string::npos || line.rfind('#', 0) == 0) continue;
      if (!header) {
        read_header(split(line), number);
        data.columns.clear();
        for (const auto& c : columns_) data.columns.push_back(c.name);
        header = true;
        continue;
      }
      data.samples.push_back(read_row(split(line), number));
    }
    if (!header) fail("", "no header line: expected column names such as A.x, A.y, omega.AB, alpha.AB, alpha.BCD");
    if (data.samples.empty()) fail("", "no data rows after the header");
    return data;
  }

 private:
  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw InputError(source_, field, problem);
  }
  std::string where(int line, size_t col) const {
    return fmt::format("line {}, column {} ({})", line, col + 1, yaml_io::backticked(columns_[col].name));
  }

  bool is_input_link(int link) const {
    for (const auto& in : scene_.inputs)
      if (in.kind == MechanismInput::Kind::Link && in.index == link) return true;
    return false;
  }
  bool is_input_joint(int joint) const {
    for (const auto& in : scene_.inputs)
      if (in.kind != MechanismInput::Kind::Link && in.index == joint) return true;
    return false;
  }

  /// Every column name this scene allows, with its meaning(s): matching whole names keeps a joint
  /// named `a` or `omega` from being read as a rate column.
  std::map<std::string, std::vector<Column>> allowed_columns() const {
    std::map<std::string, std::vector<Column>> m;
    const auto add = [&](const std::string& name, Column::Kind kind, int index) { m[name].push_back({kind, index, name}); };
    add("sample", Column::Label, 0);
    add("t", Column::Carried, 0);
    add("input_angle", Column::Carried, 0);
    const Linkage& g = scene_.linkage;
    for (int j = 0; j < g.joint_count(); ++j) {
      add(g.joint(j).name + ".x", Column::X, j);
      add(g.joint(j).name + ".y", Column::Y, j);
      if (g.joint(j).type == JointType::Prismatic) {
        add("v." + g.joint(j).name, Column::SlideV, j);
        add("a." + g.joint(j).name, Column::SlideA, j);
      }
    }
    for (int l = 0; l < g.link_count(); ++l) {
      if (l == g.ground()) continue;
      add("omega." + g.link_name(l), Column::Omega, l);
      add("alpha." + g.link_name(l), Column::Alpha, l);
    }
    return m;
  }

  std::string meaning(const Column& c) const {
    const Linkage& g = scene_.linkage;
    switch (c.kind) {
      case Column::Label: return "the sample label";
      case Column::Carried: return "a carried column";
      case Column::X: return fmt::format("the x of joint `{}`", g.joint(c.index).name);
      case Column::Y: return fmt::format("the y of joint `{}`", g.joint(c.index).name);
      case Column::Omega: return fmt::format("the omega of link `{}`", g.link_name(c.index));
      case Column::Alpha: return fmt::format("the alpha of link `{}`", g.link_name(c.index));
      case Column::SlideV: return fmt::format("the sliding velocity of joint `{}`", g.joint(c.index).name);
      case Column::SlideA: return fmt::format("the sliding acceleration of joint `{}`", g.joint(c.index).name);
    }
    return "";
  }

  Column classify(const std::string& name, int line, size_t col) const {
    const std::string here = fmt::format("line {}, column {} ({})", line, col + 1, yaml_io::backticked(name));
    if (const auto it = allowed_.find(name); it != allowed_.end()) {
      if (it->second.size() > 1)
        fail(here, fmt::format("ambiguous column: in this scene it is both {} and {}; rename a joint or link",
                               meaning(it->second[0]), meaning(it->second[1])));
      return it->second.front();
    }
    const Linkage& g = scene_.linkage;
    const auto dot = name.find('.');
    const std::string head = dot == std::string::npos ? "" : name.substr(0, dot);
    const std::string tail = yaml_io::shorten(dot == std::string::npos ? "" : name.substr(dot + 1), yaml_io::kMaxQuoted);
    if ((head == "omega" || head == "alpha") && tail == g.link_name(g.ground()))
      fail(here, "the ground link has no rates to record");
    if (head == "omega" || head == "alpha")
      fail(here, fmt::format("unknown link `{}`: the scene's links are {}", tail, fmt::join(g.link_names(), ", ")));
    if (head == "v" || head == "a") fail(here, fmt::format("`{}` is not a prismatic joint of the scene", tail));
    fail(here, "unknown column: expected sample, t, input_angle, <joint>.x, <joint>.y, omega.<link>, alpha.<link>, "
               "v.<joint> or a.<joint> with the scene's names");
  }

  void read_header(const std::vector<std::string>& names, int line) {
    if (names.size() > kMaxCsvColumns)
      fail(fmt::format("line {} (header)", line),
           fmt::format("{} columns; the limit is {} (docs/limits.md)", names.size(), kMaxCsvColumns));
    std::map<std::string, size_t> seen;
    for (size_t c = 0; c < names.size(); ++c) {
      if (names[c].empty()) fail(fmt::format("line {}, column {}", line, c + 1), "empty column name");
      if (auto it = seen.find(names[c]); it != seen.end())
        fail(fmt::format("line {}, column {} ({})", line, c + 1, yaml_io::backticked(names[c])),
             fmt::format("duplicate column (also column {})", it->second + 1));
      seen[names[c]] = c;
      columns_.push_back(classify(names[c], line, c));
    }
    const Linkage& g = scene_.linkage;
    const auto require = [&](const std::string& name, const std::string& why) {
      if (!seen.count(name)) fail(fmt::format("line {} (header)", line), fmt::format("missing column `{}` ({})", name, why));
    };
    for (const auto& j : g.joints()) {
      require(j.name + ".x", "every joint's position");
      require(j.name + ".y", "every joint's position");
    }
    for (const auto& in : scene_.inputs) {
      if (in.kind == MechanismInput::Kind::Link) {
        require("omega." + g.link_name(in.index), "the input link's omega");
        require("alpha." + g.link_name(in.index), "the input link's omega-dot");
      } else {
        require("v." + g.joint(in.index).name, "the slider input's sliding velocity");
        require("a." + g.joint(in.index).name, "the slider input's sliding acceleration");
      }
    }
    bool user = false;
    for (const auto& c : columns_)
      if ((c.kind == Column::Omega || c.kind == Column::Alpha) ? !is_input_link(c.index)
          : (c.kind == Column::SlideV || c.kind == Column::SlideA) ? !is_input_joint(c.index)
                                                                  : false)
        user = true;
    if (!user)
      fail(fmt::format("line {} (header)", line),
           "no column to check: add alpha.<link> (or omega.<link>) for a link that is not an input, or v.<joint> / "
           "a.<joint> for a prismatic joint that is not an input");
  }

  RecordedNumber number(const std::string& cell, int line, size_t col) const {
    if (cell.empty()) fail(where(line, col), "empty cell: a number is required here");
    Rational q;
    try {
      q = parse_rational(cell);
    } catch (const std::exception& e) {
      // parse_rational's message quotes the whole text: keep only its reason, quote the cell cut.
      const std::string what = e.what(), quoted = "'" + cell + "'";
      const std::string reason = what.rfind(quoted, 0) == 0 ? what.substr(quoted.size()) : " is not an exact number";
      fail(where(line, col), yaml_io::backticked(cell) + reason);
    }
    // Tolerances are computed in double: a number beyond its range would be an infinity there.
    if (cln::abs(q) > max_magnitude())
      fail(where(line, col), fmt::format("{} is beyond the range of binary64 (|x| <= 1.797e308): recorded "
                                         "data is compared with tolerances computed in double",
                                         yaml_io::backticked(cell)));
    return {q, decimal_uncertainty(cell, q), cell};
  }

  static const Rational& max_magnitude() {
    static const Rational m = ScalarTraits<double>::to_rational(std::numeric_limits<double>::max());
    return m;
  }

  MotionSample read_row(const std::vector<std::string>& cells, int line) {
    if (cells.size() != columns_.size())
      fail(fmt::format("line {}", line), fmt::format("expected {} cells (one per header column), got {}", columns_.size(), cells.size()));
    const Linkage& g = scene_.linkage;
    MotionSample s;
    s.line = line;
    s.label = fmt::format("line {}", line);
    s.x.resize(static_cast<size_t>(g.joint_count()));
    s.y = s.x;
    s.rate.resize(scene_.inputs.size());
    s.rate_dot = s.rate;
    s.user_omega.resize(static_cast<size_t>(g.link_count()));
    s.user_alpha = s.user_omega;
    s.user_slide.resize(static_cast<size_t>(g.joint_count()));
    s.user_slide_dot = s.user_slide;
    for (size_t c = 0; c < cells.size(); ++c)
      if (cells[c].size() > kMaxCsvCellBytes)
        fail(where(line, c), fmt::format("a cell of {} bytes; the limit is {} (docs/limits.md)", cells[c].size(),
                                         kMaxCsvCellBytes));
    for (size_t c = 0; c < cells.size(); ++c) {
      const Column& col = columns_[c];
      switch (col.kind) {
        case Column::Label:
          if (!cells[c].empty()) s.label = yaml_io::clean_text(cells[c]);
          break;
        case Column::Carried: (col.name == "t" ? s.t : s.input_angle) = yaml_io::clean_text(cells[c]); break;
        case Column::X: s.x[static_cast<size_t>(col.index)] = number(cells[c], line, c); break;
        case Column::Y: s.y[static_cast<size_t>(col.index)] = number(cells[c], line, c); break;
        default: read_rate(s, col, cells[c], line, c);
      }
    }
    // Printed doubles among the positions: one ulp at the scale of the row (see the header).
    double scale = 0;
    for (size_t j = 0; j < s.x.size(); ++j)
      scale = std::max({scale, std::abs(ScalarTraits<double>::from_rational(s.x[j].value)),
                        std::abs(ScalarTraits<double>::from_rational(s.y[j].value))});
    for (auto* v : {&s.x, &s.y})
      for (auto& n : *v) n.uncertainty = decimal_uncertainty(n.text, n.value, scale);
    return s;
  }

  void read_rate(MotionSample& s, const Column& col, const std::string& cell, int line, size_t c) const {
    for (size_t k = 0; k < scene_.inputs.size(); ++k) {
      const MechanismInput& in = scene_.inputs[k];
      const bool link_col = col.kind == Column::Omega || col.kind == Column::Alpha;
      const bool is_link = in.kind == MechanismInput::Kind::Link;
      if (link_col != is_link || in.index != col.index) continue;
      const bool first = col.kind == Column::Omega || col.kind == Column::SlideV;
      (first ? s.rate : s.rate_dot)[k] = number(cell, line, c);
      return;
    }
    if (cell.empty()) return;  // not recorded
    // A link's rates are indexed by link, a slider's by joint: never one by the other.
    const size_t i = static_cast<size_t>(col.index);
    switch (col.kind) {
      case Column::Omega: s.user_omega.at(i) = number(cell, line, c); break;
      case Column::Alpha: s.user_alpha.at(i) = number(cell, line, c); break;
      case Column::SlideV: s.user_slide.at(i) = number(cell, line, c); break;
      case Column::SlideA: s.user_slide_dot.at(i) = number(cell, line, c); break;
      default: throw InternalError("read_rate: not a rate column");
    }
  }

  std::string source_;
  const MechanismScene& scene_;
  std::map<std::string, std::vector<Column>> allowed_;
  std::vector<Column> columns_;
};

}  // namespace

double decimal_uncertainty(std::string_view text, const Rational& value, double scale) {
  std::string_view t = text;
  if (!t.empty() && (t[0] == '-' || t[0] == '+')) t.remove_prefix(1);
  if (t.find('/') != std::string_view::npos) return 0;
  long exponent = 0;
  if (const auto e = t.find_first_of("eE"); e != std::string_view::npos) {
    exponent = std::stol(std::string(t.substr(e + 1)));
    t = t.substr(0, e);
  }
  const auto point = t.find('.');
  if (point == std::string_view::npos && exponent == 0) return 0;  // an integer: exact
  const long decimals = point == std::string_view::npos ? 0 : static_cast<long>(t.size() - point - 1);
  std::string digits;
  for (char ch : t)
    if (ch != '.') digits += ch;
  const auto first = digits.find_first_not_of('0');
  const long significant = first == std::string::npos ? 1 : static_cast<long>(digits.size() - first);
  return digits_rule(significant, exponent - decimals, value, scale);
}

double scene_coordinate_uncertainty(const Rational& value, double scale) {
  const cln::cl_I den = cln::denominator(value);
  if (den == 1) return 0;
  cln::cl_I d = den;
  long twos = 0, fives = 0;
  while (cln::evenp(d)) d = cln::exquo(d, 2), ++twos;
  while (cln::zerop(cln::mod(d, 5))) d = cln::exquo(d, 5), ++fives;
  if (d != 1) return 0;  // a non-terminating fraction: stated exactly on purpose
  const long k = std::max(twos, fives);
  const cln::cl_I scaled = cln::abs(cln::numerator(value * cln::expt(Rational(10), k)));
  std::ostringstream text;
  text << scaled;
  if (text.str().size() < 16) return 0;  // "0.5", "117.349", "1/2": exact as written
  return one_ulp(std::max(std::abs(ScalarTraits<double>::from_rational(value)), scale));
}

MotionData parse_motion_data(const std::string& csv_text, const std::string& source, const MechanismScene& scene) {
  return DataReader(source, scene).read(csv_text);
}

MotionData load_motion_data(const std::string& path, const MechanismScene& scene) {
  return parse_motion_data(yaml_io::read_scene_file(path), path, scene);
}

}  // namespace linkproof
