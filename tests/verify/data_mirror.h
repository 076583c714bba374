// A paper's claims as data (verify/claims/mechanisms/*.yaml) against the C++ catalogue claims
// they mirror, on a bundled scene: the same verdict, and the same exact lhs and rhs for every
// comparison a data claim mirrors (docs/claims.md, "The papers' mechanism claims as data").
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "io/claim_file.h"
#include "linkproof/io/mechanism_scene.h"
#include "mechanism/mechanism_catalogue.h"
#include "mechanism/mechanism_data_claim.h"

namespace linkproof::testing_mirror {

/// Data claim `data_id` mirrors the comparison(s) `cpp_label` of the catalogue claim `cpp_id`:
/// a vector data claim the two comparisons "<cpp_label>.x" and "<cpp_label>.y", a number claim
/// the one comparison "<cpp_label>". An empty cpp_label mirrors the verdict only.
struct Mirror {
  std::string data_id, cpp_id, cpp_label;
};

inline std::string text(const Defined<Rational>& v) {
  return v.has_value() ? format_rational(v.get()) : "undefined (" + v.quantity() + ": " + v.reason() + ")";
}

inline const Comparison<Rational>* find_comparison(const ClaimSides<Rational>& s, const std::string& label) {
  for (const Comparison<Rational>& c : s.instances)
    if (c.label_head == label) return &c;
  return nullptr;
}

/// Runs the mirrors on `scene_file`; every claim of `data_file` must be in `mirrors`.
inline void expect_mirrored(const std::vector<MechanismClaim>& catalogue, const std::string& data_file,
                            const std::string& scene_file, const std::vector<Mirror>& mirrors) {
  const std::string root = LINKPROOF_SOURCE_DIR;
  const MechanismScene scene = load_mechanism_scene(root + "/" + scene_file);
  const MechanismSolution<Rational> truth = solve_mechanism_exact(scene);
  const MechanismContext ctx{scene, truth};
  MechanismClaimFile file = load_mechanism_claim_file(root + "/" + data_file);
  std::map<std::string, const MechanismDataClaim*> data;
  for (MechanismDataClaim& c : file.claims) {
    bind_mechanism_claim(c, scene);
    data[c.info.id] = &c;
  }
  std::map<std::string, const MechanismClaim*> cpp;
  for (const MechanismClaim& c : catalogue) cpp[c.info.id] = &c;
  std::set<std::string> mirrored;
  const MechanismFrame frame(scene, truth.motion);
  for (const Mirror& m : mirrors) {
    SCOPED_TRACE(m.data_id + " mirrors " + m.cpp_id + (m.cpp_label.empty() ? "" : " [" + m.cpp_label + "]"));
    ASSERT_TRUE(data.count(m.data_id)) << "no data claim " << m.data_id << " in " << data_file;
    ASSERT_TRUE(cpp.count(m.cpp_id)) << "no catalogue claim " << m.cpp_id;
    mirrored.insert(m.data_id);
    const MechanismDataClaim& d = *data[m.data_id];
    const MechanismClaim& c = *cpp[m.cpp_id];
    ASSERT_TRUE(!c.applies || c.applies(ctx));
    const ClaimOutcome data_outcome = run_mechanism_claim(to_mechanism_claim(d), ctx);
    const ClaimOutcome cpp_outcome = run_mechanism_claim(c, ctx);
    EXPECT_EQ(data_outcome.verdict, cpp_outcome.verdict);
    EXPECT_EQ(data_outcome.info.expected, cpp_outcome.info.expected);
    if (m.cpp_label.empty()) continue;
    const ClaimSides<Rational> ds = evaluate_mechanism_claim(d, frame);
    const ClaimSides<Rational> cs = c.evaluate(ctx);
    const bool vector = d.lhs.kind() == ClaimKind::Vector;
    for (const Comparison<Rational>& dc : ds.instances) {
      const std::string label = vector ? m.cpp_label + "." + dc.label_head : m.cpp_label;
      const Comparison<Rational>* cc = find_comparison(cs, label);
      ASSERT_NE(cc, nullptr) << "the catalogue claim has no comparison '" << label << "'";
      ASSERT_TRUE(dc.lhs.has_value() && dc.rhs.has_value()) << text(dc.lhs) << " / " << text(dc.rhs);
      ASSERT_TRUE(cc->lhs.has_value() && cc->rhs.has_value()) << text(cc->lhs) << " / " << text(cc->rhs);
      EXPECT_EQ(text(dc.lhs), text(cc->lhs)) << label << " lhs";
      EXPECT_EQ(text(dc.rhs), text(cc->rhs)) << label << " rhs";
    }
  }
  for (const auto& [id, claim] : data) EXPECT_TRUE(mirrored.count(id)) << id << " of " << data_file << " mirrors nothing";
}

}  // namespace linkproof::testing_mirror
