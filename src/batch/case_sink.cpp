#include "linkproof/batch/case_sink.h"

#include "linkproof/batch/batch_sweep.h"
#include "linkproof/report/sweep_lines.h"

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

}  // namespace linkproof
