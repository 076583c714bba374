#include "scene_ask.h"

#include <fmt/format.h>

#include <cctype>

#include "yaml_document.h"

namespace linkproof::yaml_io {

namespace {

constexpr const char* kForms =
    "omega(S), omega_dot(S), links: [...], points: [...], claims: [...] or arithmetic: NAME (docs/ask.md)";

[[noreturn]] void fail(const std::string& source, const std::string& field, const std::string& problem) {
  throw InputError(source, field, shorten(problem, kMaxProblem));
}

std::string trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return std::string(s);
}

// "omega(4)", "omega_dot( 5 )", "omega_dot(\"5\")": the rate and its subject.
AskedRate read_rate(const std::string& text, const std::string& source, const std::string& field) {
  const auto open = text.find('(');
  const std::string head = trimmed(std::string_view(text).substr(0, open == std::string::npos ? text.size() : open));
  if (open == std::string::npos || text.back() != ')' || (head != "omega" && head != "omega_dot"))
    fail(source, field, "expected an item " + std::string(kForms) + ", got " + backticked(shorten(text, kMaxQuoted)));
  std::string subject = trimmed(std::string_view(text).substr(open + 1, text.size() - open - 2));
  if (subject.size() >= 2 && (subject.front() == '"' || subject.front() == '\'') && subject.back() == subject.front())
    subject = subject.substr(1, subject.size() - 2);
  if (subject.empty()) fail(source, field, "expected a side or link inside " + head + "(...), got nothing");
  return AskedRate{head == "omega_dot", AskedName{clean_text(subject), field}};
}

std::vector<AskedName> read_names(const YAML::Node& node, const std::string& source, const std::string& field,
                                  const char* what) {
  if (!node.IsSequence()) fail(source, field, fmt::format("expected a list of {}, got {}", what, kind_of(node)));
  // An empty list asks for nothing: a slip, not a request (leave the item out instead).
  if (node.size() == 0) fail(source, field, fmt::format("the list of {} is empty; leave the item out", what));
  std::vector<AskedName> out;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string f = fmt::format("{}[{}]", field, i);
    if (!node[i].IsScalar() || node[i].Scalar().empty())
      fail(source, f, fmt::format("expected one of the {} (a name), got {}", what, kind_of(node[i])));
    for (const AskedName& seen : out)
      if (seen.name == node[i].Scalar()) fail(source, f, backticked(node[i].Scalar()) + " is asked twice");
    out.push_back(AskedName{clean_text(node[i].Scalar()), f});
  }
  return out;
}

}  // namespace

SceneAsk read_scene_ask(const YAML::Node& node, const std::string& source) {
  if (!node.IsSequence())
    fail(source, "ask", "expected a list of items " + std::string(kForms) + ", got " + kind_of(node));
  if (node.size() == 0) fail(source, "ask", "the list is empty; leave `ask` out to compute everything");
  SceneAsk ask;
  bool links = false, points = false;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node item = node[i];
    const std::string field = fmt::format("ask[{}]", i);
    if (item.IsScalar()) {
      const AskedRate rate = read_rate(item.Scalar(), source, field);
      for (const AskedRate& seen : ask.rates)
        if (seen.dot == rate.dot && seen.subject.name == rate.subject.name)
          fail(source, field, backticked(rate.text()) + " is asked twice");
      ask.rates.push_back(rate);
      continue;
    }
    if (!item.IsMap() || item.size() != 1)
      fail(source, field, "expected an item " + std::string(kForms) + ", got " + kind_of(item));
    const auto kv = *item.begin();
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "";
    const std::string f = field + "." + shorten(key, kMaxQuoted);
    const auto once = [&](bool& seen) {
      if (seen) fail(source, f, "`" + key + "` is given twice in `ask`; list every name in one item");
      seen = true;
    };
    if (key == "claims") {
      if (ask.claims) fail(source, f, "`claims` is given twice in `ask`; list every claim in one item");
      ask.claims = read_names(kv.second, source, f, "claim ids");
    } else if (key == "links") {
      once(links);
      ask.links = read_names(kv.second, source, f, "link names");
    } else if (key == "points") {
      once(points);
      ask.points = read_names(kv.second, source, f, "joint or point names");
    } else if (key == "arithmetic") {
      if (ask.arithmetic) fail(source, f, "`arithmetic` is given twice in `ask`");
      const std::string name = kv.second.IsScalar() ? kv.second.Scalar() : "";
      ask.arithmetic = parse_arithmetic(name);
      if (!ask.arithmetic)
        fail(source, f,
             "expected one of exact, double, long-double, mp30, mp50, mp100, mp1000, got " +
                 (kv.second.IsScalar() ? backticked(shorten(name, kMaxQuoted)) : kind_of(kv.second)));
    } else {
      fail(source, f, "unknown item " + backticked(key) + "; expected " + kForms);
    }
  }
  return ask;
}

void emit_ask(YAML::Emitter& out, const SceneAsk& ask) {
  out << YAML::Key << "ask" << YAML::Value << YAML::BeginSeq;
  for (const AskedRate& r : ask.rates) out << YAML::DoubleQuoted << r.text();
  const auto list = [&](const char* key, const std::vector<AskedName>& names) {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (const AskedName& n : names) out << YAML::DoubleQuoted << n.name;
    out << YAML::EndSeq << YAML::EndMap;
  };
  if (!ask.links.empty()) list("links", ask.links);
  if (!ask.points.empty()) list("points", ask.points);
  if (ask.claims) list("claims", *ask.claims);
  if (ask.arithmetic)
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "arithmetic" << YAML::Value
        << std::string(to_string(*ask.arithmetic)) << YAML::EndMap;
  out << YAML::EndSeq;
}

}  // namespace linkproof::yaml_io
