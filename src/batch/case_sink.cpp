#include "batch/case_sink.h"

#include <algorithm>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "batch/batch_sweep.h"

namespace linkproof {

CaseSink::CaseSink(const std::vector<Claim>& catalogue, const SweepOptions& options, ResultFile* file,
                   std::string scenes_dir)
    : options_(options), tally_(catalogue, options), file_(file), scenes_dir_(std::move(scenes_dir)) {}

void CaseSink::add(SweepCase& c, bool write, const std::string& origin_file, const std::string& origin_field) {
  if (const auto missing = tally_.add(c))
    throw InputError(origin_file, origin_field,
                     "case " + std::to_string(c.k) + " lacks the evidence of " + *missing +
                         " that the report keeps (a file written by another rule, or edited)");
  if (write && file_ != nullptr) file_->append(sweep_case_line(c, options_.arithmetic));
  if (!scenes_dir_.empty() && tally_.has_unexpected(c)) write_sweep_scene(scenes_dir_, c);
}

void check_case_identity(const SweepLine& line, long expected, const SweepOptions& o,
                         const std::vector<Claim>& catalogue, const std::string& file, const std::string& where) {
  const SweepCase& c = *line.sweep_case;
  const auto [n, index] = SweepPlan(o).at(expected);
  if (c.k != expected || c.polygon.seed != o.seed || c.polygon.n != n || c.polygon.index != index ||
      line.arithmetic != o.arithmetic)
    throw InputError(file, where,
                     fmt::format("case {} (seed {}, n = {}, index {}, {}) is not the next case of this sweep, which is "
                                 "case {} (seed {}, n = {}, index {}, {}): the file belongs to another sweep or shard",
                                 c.k, c.polygon.seed, c.polygon.n, c.polygon.index, to_string(line.arithmetic),
                                 expected, o.seed, n, index, to_string(o.arithmetic)));
  // The claims: exactly those a run of this catalogue judges at n, and the rest not applicable.
  std::set<std::string> known;
  for (const Claim& claim : catalogue) known.insert(claim.info.id);
  for (const auto& [id, verdict] : c.verdicts)
    if (!known.count(id))
      throw InputError(file, where + ".verdicts",
                       "a verdict of an unknown claim " + id + " (not a claim this sweep checks)");
  std::vector<std::string> not_applicable;
  for (const Claim& claim : catalogue) {
    const std::string& id = claim.info.id;
    const bool judged = c.verdicts.count(id) > 0;
    if (!claim.info.applies_to(n)) {
      not_applicable.push_back(id);
      if (judged)
        throw InputError(file, where + ".verdicts", fmt::format("a verdict of {}, which does not apply at n = {}", id, n));
    } else if (!judged) {
      const bool listed = std::find(c.not_applicable.begin(), c.not_applicable.end(), id) != c.not_applicable.end();
      throw InputError(file, where + ".verdicts",
                       fmt::format("has no verdict of {}, which applies at n = {}{}", id, n,
                                   listed ? " (it is listed as not applicable)" : ""));
    }
  }
  if (c.not_applicable != not_applicable)
    throw InputError(file, where + ".not_applicable",
                     fmt::format("must list the claims that do not apply at n = {}, in catalogue order: [{}]", n,
                                 fmt::join(not_applicable, ", ")));
}

}  // namespace linkproof
