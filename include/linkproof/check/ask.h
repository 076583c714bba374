// What a scene asks for (its optional `ask` field, docs/ask.md): the outputs, the claims and
// the arithmetic. A check derives only what the asked items need; without `ask` it computes
// everything, as before.
//
//   ask: [omega_dot(4), claims: [eq22]]                 # polygon: one rate and one claim
//   ask: [links: ["5"], arithmetic: double]             # mechanism: one link's omega, omega-dot
//
// Items, in any order:
//   omega(S), omega_dot(S)   a rate: polygon side S = 1..n (relative to side n), or mechanism link S
//   links: [names]           mechanisms: omega and omega-dot of each link (relative to the ground)
//   points: [names]          mechanisms: velocity and acceleration of each joint or tracer point
//   claims: [ids]            only these claims (a full id, or its ending after a dot: `eq22`);
//                            without a `claims` item no claim is evaluated
//   arithmetic: NAME         the arithmetic (`--arith` on the command line takes precedence)
// An `ask` with only `arithmetic` computes everything in that arithmetic.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "linkproof/check/arithmetic.h"
#include "linkproof/core/error.h"

namespace linkproof {

/// A name given in `ask`, with the field it came from (for error messages), e.g. "ask[1].claims[0]".
struct AskedName {
  std::string name;
  std::string field;
};

/// omega(subject) or omega_dot(subject).
struct AskedRate {
  bool dot = false;
  AskedName subject;
  std::string text() const { return std::string(dot ? "omega_dot(" : "omega(") + subject.name + ")"; }
};

struct SceneAsk {
  std::vector<AskedRate> rates;
  std::vector<AskedName> links, points;
  std::optional<std::vector<AskedName>> claims;
  std::optional<Arithmetic> arithmetic;

  /// True if the ask names an output or a claims list (otherwise everything is computed).
  bool restricts() const { return !rates.empty() || !links.empty() || !points.empty() || claims.has_value(); }
  /// The items as written, one string each ("omega_dot(4)", "claims: eq22, eq9"): for reports.
  std::vector<std::string> describe() const {
    std::vector<std::string> out;
    for (const AskedRate& r : rates) out.push_back(r.text());
    const auto list = [&](const char* key, const std::vector<AskedName>& names) {
      if (names.empty()) return;
      std::string s = std::string(key) + ":";
      for (size_t k = 0; k < names.size(); ++k) s += (k ? ", " : " ") + names[k].name;
      out.push_back(s);
    };
    list("links", links);
    list("points", points);
    if (claims) {
      if (claims->empty()) out.push_back("claims: none");
      list("claims", *claims);
    }
    if (arithmetic) out.push_back("arithmetic: " + std::string(to_string(*arithmetic)));
    return out;
  }
};

/// True if `id` is the claim id `name` or ends with "." + name.
inline bool claim_id_matches(const std::string& id, const std::string& name) {
  return id == name || (id.size() > name.size() && id.ends_with("." + name));
}

/// The claims of `all` the ask names, in catalogue order (every claim if the ask does not
/// restrict; none if it restricts without a `claims` item). A name that matches no claim is an
/// InputError(source, its field, ...) listing the ids there are. C has `info.id`.
template <class C>
std::vector<C> asked_claims(const std::vector<C>& all, const std::optional<SceneAsk>& ask, const std::string& source) {
  if (!ask || !ask->restricts()) return all;
  if (!ask->claims) return {};
  for (const AskedName& n : *ask->claims) {
    bool found = false;
    for (const C& c : all) found = found || claim_id_matches(c.info.id, n.name);
    if (found) continue;
    std::string ids;
    for (const C& c : all) ids += (ids.empty() ? "" : ", ") + c.info.id;
    throw InputError(source, n.field, "no claim named `" + n.name + "` here; the claims are: " + ids);
  }
  std::vector<C> out;
  for (const C& c : all)
    for (const AskedName& n : *ask->claims)
      if (claim_id_matches(c.info.id, n.name)) {
        out.push_back(c);
        break;
      }
  return out;
}

}  // namespace linkproof
