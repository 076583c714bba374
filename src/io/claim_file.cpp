#include "io/claim_file.h"

#include <cctype>
#include <charconv>
#include <set>

#include "claims/claim_indices.h"
#include "linkproof/core/error.h"
#include "yaml_document.h"

namespace linkproof {

namespace {

/// Maps offsets in a scalar's content to file positions: the scalar's non-blank characters
/// appear in the file in the same order (plain, quoted without escapes, literal or folded).
PositionMap positions_in_file(const std::string& file_text, const YAML::Mark& mark, const std::string& content) {
  return [&file_text, mark, content](size_t offset) {
    size_t pos = mark.pos < 0 ? 0 : static_cast<size_t>(mark.pos);
    if (pos < file_text.size() && (file_text[pos] == '|' || file_text[pos] == '>')) {
      while (pos < file_text.size() && file_text[pos] != '\n') ++pos;
    } else if (pos < file_text.size() && (file_text[pos] == '"' || file_text[pos] == '\'')) {
      ++pos;
    }
    size_t want = 0;  // non-blank characters of the content before `offset`
    for (size_t i = 0; i < offset && i < content.size(); ++i)
      if (!std::isspace(static_cast<unsigned char>(content[i]))) ++want;
    size_t seen = 0, at = pos;
    for (size_t i = pos; i < file_text.size(); ++i) {
      if (std::isspace(static_cast<unsigned char>(file_text[i]))) continue;
      at = i;
      if (seen == want) break;
      ++seen;
      at = i + 1;
    }
    int line = 1, column = 1;
    for (size_t i = 0; i < at && i < file_text.size(); ++i) {
      if (file_text[i] == '\n') { ++line; column = 1; } else { ++column; }
    }
    return std::pair<int, int>{line, column};
  };
}

constexpr std::size_t kMaxClaimFileNodes = 100000;
constexpr int kMaxClaimFileDepth = 500;  // as deep as the YAML parser itself nests (yaml_document.cpp)

/// yaml-cpp keeps the first of two equal keys and `map[key]` reads it: a repeated key anywhere in
/// a claim file is refused instead (the second `rhs:` would otherwise be ignored silently).
/// `visits` bounds the walk: aliases can make a small file a huge tree ("billion laughs").
/// `depth` bounds it too: an alias inside its own anchor (`a: &x [*x]`) makes a cycle, which the
/// parser's own nesting limit does not see, and the walk would end only when the stack does.
void refuse_repeated_keys(const YAML::Node& node, const std::string& source, const std::string& where,
                          std::size_t& visits, int depth = 0) {
  // The field as far as it is worth printing (a cycle repeats it: a[0][0][0]...).
  const auto shown_where = [&] { return where.size() > 80 ? where.substr(0, 80) + "..." : where; };
  if (++visits > kMaxClaimFileNodes)
    throw InputError(source, shown_where(), "the document expands (through aliases) to more than " +
                                          std::to_string(kMaxClaimFileNodes) + " nodes (docs/limits.md)");
  if (depth > kMaxClaimFileDepth)
    throw InputError(source, shown_where(), "the document nests (through aliases) more than " + std::to_string(kMaxClaimFileDepth) +
                                          " levels deep: an alias inside its own anchor? (docs/limits.md)");
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i)
      refuse_repeated_keys(node[i], source, where + "[" + std::to_string(i) + "]", visits, depth + 1);
  } else if (node.IsMap()) {
    std::set<std::string> seen;
    for (const auto& kv : node) {
      const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
      const std::string field = (where.empty() ? "" : where + ".") + yaml_io::shorten(key, yaml_io::kMaxQuoted);
      if (!seen.insert(key).second) throw InputError(source, field, "field " + yaml_io::backticked(key) + " is given twice");
      refuse_repeated_keys(kv.second, source, field, visits, depth + 1);
    }
  }
}

class ClaimFileReader {
 public:
  ClaimFileReader(const std::string& text, const std::string& source) : text_(text), source_(source) {}

  ClaimFile read(const YAML::Node& doc) {
    ClaimFile f;
    f.source = source_;
    read_list(doc, [&](const YAML::Node& n, const std::string& where, const std::string& paper,
                       const std::string& prefix) {
      f.claims.push_back(read_claim(n, where, paper, prefix));
      return f.claims.back().info.id;
    });
    return f;
  }

  MechanismClaimFile read_mechanism(const YAML::Node& doc) {
    MechanismClaimFile f;
    f.source = source_;
    read_list(doc, [&](const YAML::Node& n, const std::string& where, const std::string& paper,
                       const std::string& prefix) {
      f.claims.push_back(read_mechanism_claim(n, where, paper, prefix));
      return f.claims.back().info.id;
    });
    return f;
  }

 private:
  // The top-level map and its list of claims; `read_one(node, "claims[i]", paper, prefix)`
  // reads one claim and returns its id (ids must be unique).
  template <class ReadOne>
  void read_list(const YAML::Node& doc, ReadOne read_one) const {
    if (!doc.IsMap()) fail("", "expected a map with the field `claims`");
    known_keys(doc, "", {"paper", "id_prefix", "claims"});
    const std::string paper = optional_string(doc, "paper", "");
    const std::string prefix = optional_string(doc, "id_prefix", "");
    const YAML::Node list = doc["claims"];
    if (!list) fail("claims", "missing: the list of claims");
    if (!list.IsSequence() || list.size() == 0) fail("claims", "expected a non-empty list of claims");
    std::set<std::string> ids;
    for (size_t i = 0; i < list.size(); ++i) {
      const std::string id = read_one(list[i], "claims[" + std::to_string(i) + "]", paper, prefix);
      if (!ids.insert(id).second) fail("claims[" + std::to_string(i) + "].id", "repeated id '" + id + "'");
    }
  }

  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw InputError(source_, field, problem);
  }

  void known_keys(const YAML::Node& map, const std::string& where, const std::set<std::string>& keys) const {
    for (const auto& kv : map) {
      const std::string k = kv.first.IsScalar() ? kv.first.Scalar() : "?";
      if (!keys.count(k)) {
        std::string list;
        for (const auto& x : keys) list += (list.empty() ? "" : ", ") + x;
        fail(where.empty() ? k : where + "." + k, "unknown field (expected one of: " + list + ")");
      }
    }
  }

  std::string required_string(const YAML::Node& map, const std::string& key, const std::string& where) const {
    const YAML::Node n = map[key];
    if (!n) fail(where + "." + key, "missing");
    if (!n.IsScalar() || n.Scalar().empty()) fail(where + "." + key, "expected a non-empty string");
    return yaml_io::clean_text(n.Scalar());
  }

  std::string optional_string(const YAML::Node& map, const std::string& key, const std::string& fallback) const {
    const YAML::Node n = map[key];
    if (!n) return fallback;
    if (!n.IsScalar()) fail(key, "expected a string");
    return yaml_io::clean_text(n.Scalar());
  }

  static bool parse_int(const std::string& s, int& v) {
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && p == s.data() + s.size();
  }

  void read_range(const YAML::Node& n, const std::string& field, ClaimInfo& info) const {
    if (!n) return;
    if (!n.IsScalar()) fail(field, "expected N, \"A..B\" or \"A..\"");
    const std::string s = n.Scalar();
    const auto dots = s.find("..");
    int a = 0, b = 0;
    const bool ok = dots == std::string::npos
                        ? (parse_int(s, a) && (b = a, true))
                        : parse_int(s.substr(0, dots), a) &&
                              (s.size() == dots + 2 ? (b = 0, true) : parse_int(s.substr(dots + 2), b));
    if (!ok || a < 4 || (b != 0 && b < a) || a > kMaxClaimSides || b > kMaxClaimSides)
      fail(field, "'" + s + "' is not N, A..B or A.. with 4 <= A <= B <= " + std::to_string(kMaxClaimSides));
    info.min_n = a;
    info.max_n = b;
  }

  ClaimReading read_reading(const YAML::Node& n, const std::string& field) const {
    ClaimReading r;
    if (!n) return r;
    if (!n.IsSequence()) fail(field, "expected a list of readings");
    for (size_t i = 0; i < n.size(); ++i) {
      const std::string name = n[i].IsScalar() ? n[i].Scalar() : "";
      if (name == "undisplaced_start") r.construction.displaced_start = false;
      else if (name == "beta_towards_p") r.construction.beta_towards_p_prime = false;
      else if (name == "reversed_beta") r.construction.beta_ccw_positive = false;
      else if (name == "unsigned_ratios") r.construction.signed_ratios = false;
      else if (name == "unsigned_phi") r.signed_phi = false;
      else
        fail(field + "[" + std::to_string(i) + "]",
             "unknown reading '" + name +
                 "' (expected undisplaced_start, beta_towards_p, reversed_beta, unsigned_ratios, unsigned_phi)");
    }
    return r;
  }

  ClaimExpression read_expression(const YAML::Node& map, const std::string& key, const std::string& where,
                                  bool j_free) const {
    const YAML::Node n = map[key];
    const std::string field = where + "." + key;
    if (!n) fail(field, "missing");
    if (!n.IsScalar() || n.Scalar().empty()) fail(field, "expected an expression (a string)");
    ExpressionContext ctx{source_, field, j_free};
    return ClaimExpression::parse(n.Scalar(), ctx, positions_in_file(text_, n.Mark(), n.Scalar()));
  }

  // id, source, statement, expected and note: the fields every claim has.
  ClaimInfo read_info(const YAML::Node& n, const std::string& where, const std::string& paper,
                      const std::string& prefix) const {
    ClaimInfo info;
    const std::string id = required_string(n, "id", where);
    for (char ch : id)
      if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.' && ch != '_' && ch != '-')
        fail(where + ".id", "'" + id + "' may only contain letters, digits, '.', '_' and '-'");
    info.id = prefix + id;
    const std::string src = required_string(n, "source", where);
    info.source = paper.empty() ? src : paper + ", " + src;
    info.statement = required_string(n, "statement", where);
    if (const YAML::Node e = n["expected"]) {
      const std::string v = e.IsScalar() ? e.Scalar() : "";
      if (v == "holds") info.expected = Expectation::Holds;
      else if (v == "fails") info.expected = Expectation::Fails;
      else fail(where + ".expected", "expected 'holds' or 'fails', got '" + v + "'");
    }
    if (const YAML::Node e = n["note"]) {
      if (!e.IsScalar()) fail(where + ".note", "expected a string");
      info.note = yaml_io::clean_text(e.Scalar());
    }
    return info;
  }

  MechanismExpression read_mechanism_expression(const YAML::Node& map, const std::string& key,
                                                const std::string& where, const std::string& id) const {
    const YAML::Node n = map[key];
    const std::string field = where + "." + key;
    if (!n) fail(field, "missing");
    if (!n.IsScalar() || n.Scalar().empty()) fail(field, "expected an expression (a string)");
    ExpressionContext ctx{source_, field + " (claim '" + id + "')", false};
    return MechanismExpression::parse(n.Scalar(), ctx, positions_in_file(text_, n.Mark(), n.Scalar()));
  }

  MechanismDataClaim read_mechanism_claim(const YAML::Node& n, const std::string& where, const std::string& paper,
                                          const std::string& prefix) const {
    if (!n.IsMap()) fail(where, "expected a map (id, source, statement, lhs, rhs, ...)");
    known_keys(n, where, {"id", "source", "statement", "expected", "note", "lhs", "rhs"});
    MechanismDataClaim c;
    c.info = read_info(n, where, paper, prefix);
    c.field = where;
    c.lhs = read_mechanism_expression(n, "lhs", where, c.info.id);
    c.rhs = read_mechanism_expression(n, "rhs", where, c.info.id);
    if (c.lhs.kind() != c.rhs.kind())
      fail(where + " (claim '" + c.info.id + "')",
           "lhs is " + describe(c.lhs.kind()) + " and rhs " + describe(c.rhs.kind()) +
               ": a claim compares two numbers or two vectors");
    return c;
  }

  DataClaim read_claim(const YAML::Node& n, const std::string& where, const std::string& paper,
                       const std::string& prefix) const {
    if (!n.IsMap()) fail(where, "expected a map (id, source, statement, lhs, rhs, ...)");
    known_keys(n, where, {"id", "source", "statement", "expected", "note", "n", "for_each", "reading", "lhs", "rhs"});
    DataClaim c;
    c.info = read_info(n, where, paper, prefix);
    read_range(n["n"], where + ".n", c.info);
    if (const YAML::Node e = n["for_each"]) {
      if (!e.IsScalar() || e.Scalar() != "j") fail(where + ".for_each", "expected 'j' (one statement per input j)");
      c.for_each_j = true;
    }
    c.reading = read_reading(n["reading"], where + ".reading");
    c.lhs = read_expression(n, "lhs", where, c.for_each_j);
    c.rhs = read_expression(n, "rhs", where, c.for_each_j);
    for (const ClaimExpression* side : {&c.lhs, &c.rhs}) check_claim_indices(*side, c.info.min_n, c.info.max_n);
    return c;
  }

  const std::string& text_;
  const std::string& source_;
};

}  // namespace

namespace {

template <class Read>
auto read_claim_document(const std::string& yaml_text, const std::string& source, Read read) {
  const YAML::Node doc =
      yaml_io::parse_single_document(yaml_text, source, "empty document: expected a map with the field `claims`");
  std::size_t visits = 0;
  refuse_repeated_keys(doc, source, "", visits);
  try {
    return read(ClaimFileReader(yaml_text, source), doc);
  } catch (const YAML::Exception& e) {
    throw InputError(source, "", std::string("cannot read the YAML: ") + e.what());
  }
}

}  // namespace

ClaimFile parse_claim_file(const std::string& yaml_text, const std::string& source) {
  return read_claim_document(yaml_text, source, [](ClaimFileReader r, const YAML::Node& doc) { return r.read(doc); });
}

MechanismClaimFile parse_mechanism_claim_file(const std::string& yaml_text, const std::string& source) {
  return read_claim_document(yaml_text, source,
                             [](ClaimFileReader r, const YAML::Node& doc) { return r.read_mechanism(doc); });
}

MechanismClaimFile load_mechanism_claim_file(const std::string& path) {
  MechanismClaimFile file = parse_mechanism_claim_file(yaml_io::read_scene_file(path), path);
  for (MechanismDataClaim& c : file.claims) c.info.file = path;
  return file;
}

ClaimFile parse_user_claim_file(const std::string& yaml_text, const std::string& path) {
  ClaimFile file = parse_claim_file(yaml_text, path);
  for (DataClaim& c : file.claims) c.info.file = path;
  return file;
}

ClaimFile load_claim_file(const std::string& path) { return parse_user_claim_file(yaml_io::read_scene_file(path), path); }

}  // namespace linkproof
