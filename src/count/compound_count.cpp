#include "count/compound_count.h"

#include <algorithm>
#include <charconv>
#include <chrono>

#include "linkproof/core/error.h"

namespace linkproof {

std::vector<std::vector<int>> parse_polygon_list(const std::string& text, const std::string& source,
                                                 const std::string& field) {
  std::vector<std::vector<int>> loops;
  const auto bad = [&](const std::string& why) {
    return InputError(source, field, "'" + text + "': " + why + " (expected loops like 1-2-3-4-0,1-5-7-4-0)");
  };
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    std::vector<int> loop;
    size_t p = 0;
    while (p <= item.size()) {
      const size_t dash = std::min(item.find('-', p), item.size());
      int v = 0;
      const char* b = item.data() + p;
      const char* e = item.data() + dash;
      auto [end, ec] = std::from_chars(b, e, v);
      if (b == e || ec != std::errc() || end != e) throw bad("'" + item + "' is not a list of link numbers");
      loop.push_back(v);
      p = dash + 1;
    }
    if (loop.size() < 3) throw bad("a loop needs at least 3 links");
    std::vector<int> sorted = loop;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) throw bad("a link repeats in '" + item + "'");
    loops.push_back(std::move(loop));
    start = comma + 1;
  }
  return loops;
}

BodyPolygon construct_loop_polygon(const CompoundMechanism& m, const std::vector<int>& loop) {
  const int n = static_cast<int>(loop.size());
  std::vector<Vec2<Rational>> joints;
  for (int j = 0; j < n; ++j) {
    const int prev = loop[static_cast<size_t>((j + n - 1) % n)], cur = loop[static_cast<size_t>(j)];
    for (int l : {prev, cur})
      if (l < 0 || l >= m.links)
        throw InputError(m.name, "polygons", "link " + std::to_string(l) + " does not exist (links 0.." +
                                                 std::to_string(m.links - 1) + ")");
    const auto it = m.joints.find({std::min(prev, cur), std::max(prev, cur)});
    if (it == m.joints.end())
      throw InputError(m.name, "polygons", "links " + std::to_string(prev) + " and " + std::to_string(cur) +
                                               " share no joint");
    joints.push_back(it->second);  // K_j: start of side j (link cur), joint with the previous link
  }
  return {loop, Polygon<Rational>(std::move(joints))};
}

std::optional<Rational> CompoundCount::relative_omega_dot(int a, int b) const {
  const auto& x = omega_dot[static_cast<size_t>(a)];
  const auto& y = omega_dot[static_cast<size_t>(b)];
  if (!x || !y) return std::nullopt;
  return *x - *y;
}

namespace {

/// rate_{input,fixed} = value as a relation.
RateRelation input_relation(const RelativeRates& rates, const CompoundMechanism& m, const Rational& value) {
  return {"input", make_sparse_row<Rational>({rates.term(m.input_link, m.fixed_link, 1)}), value};
}

/// Rates of every link relative to the fixed one, where the echelon determines them.
std::vector<std::optional<Rational>> rates_to_fixed(const RowEchelon<Rational>& e, const RelativeRates& rates,
                                                    int fixed) {
  std::vector<std::optional<Rational>> out(static_cast<size_t>(rates.bodies()));
  for (int b = 0; b < rates.bodies(); ++b) {
    if (b == fixed) {
      out[static_cast<size_t>(b)] = Rational(0);
      continue;
    }
    // rate_{b,fixed} = x_{b,fixed} if b < fixed, else -x_{fixed,b}.
    const auto v = e.determined_value(rates.column(std::min(b, fixed), std::max(b, fixed)));
    if (v) out[static_cast<size_t>(b)] = b < fixed ? *v : -*v;
  }
  return out;
}

}  // namespace

CompoundCount count_compound(const CompoundMechanism& m, const std::vector<std::vector<int>>& loops) {
  const RelativeRates rates(m.links);
  std::vector<BodyPolygon> polygons;
  for (const auto& l : loops) polygons.push_back(construct_loop_polygon(m, l));
  const std::vector<RateRelation> triangles = triangle_relations(rates);

  CompoundCount c;
  c.unknowns = rates.columns();

  // Velocities: triangles + input + (5), (6) of every polygon.
  {
    const auto t0 = std::chrono::steady_clock::now();
    RowEchelon<Rational> e(rates.columns());
    add_and_rank(e, triangles);
    add_and_rank(e, {input_relation(rates, m, m.input_omega)});
    for (const auto& p : polygons) add_and_rank(e, velocity_relations(rates, p));
    c.velocity = {e.relations(), e.columns(), e.rank(), e.augmented_rank(),
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
    c.omega = rates_to_fixed(e, rates, m.fixed_link);
  }

  // Accelerations, step by step.
  RowEchelon<Rational> e(rates.columns());
  c.triangles = add_and_rank(e, triangles);
  c.with_input = add_and_rank(e, {input_relation(rates, m, m.input_omega_dot)});
  c.with_input.seconds += c.triangles.seconds;
  c.omega_dot.assign(static_cast<size_t>(m.links), std::nullopt);
  const bool velocities_known = c.velocity.consistent() &&
                                std::all_of(c.omega.begin(), c.omega.end(), [](const auto& w) { return w.has_value(); });
  if (!velocities_known) return c;
  std::vector<Rational> omega;
  for (const auto& w : c.omega) omega.push_back(*w);
  std::vector<RateRelation> acc;
  for (const auto& p : polygons)
    for (auto& r : acceleration_relations(rates, p, omega)) acc.push_back(std::move(r));
  RankResult r = add_and_rank(e, acc);
  r.seconds += c.with_input.seconds;
  c.with_polygons = r;
  if (r.consistent()) c.omega_dot = rates_to_fixed(e, rates, m.fixed_link);
  return c;
}

}  // namespace linkproof
