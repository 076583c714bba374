// An index is read as a machine integer: one beyond that range wrapped (2^64 + 1 read as 1), so
// `omega[1] = omega[18446744073709551617]` was proved for every n. It is refused when read.
#include <gtest/gtest.h>

#include <string>

#include "io/claim_file.h"
#include "linkproof/core/error.h"

namespace linkproof {
namespace {

std::string claim_with_rhs(const std::string& rhs) {
  return "claims:\n  - id: wrap\n    source: test\n    statement: s\n    lhs: omega[1]\n    rhs: \"" + rhs + "\"\n";
}

TEST(HugeIndex, AnIndexBeyondTheMachineRangeIsRefusedWhenReadNotWrapped) {
  for (const std::string rhs : {"omega[18446744073709551617]", "omega[4294967297]",
                                "sum_j(omega[18446744073709551616*j + 1])", "r[n - 18446744073709551616]"}) {
    try {
      parse_user_claim_file(claim_with_rhs(rhs), "wrap.yaml");
      ADD_FAILURE() << rhs << ": read";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("wrap.yaml"), std::string::npos) << m;
      EXPECT_NE(m.find("beyond"), std::string::npos) << rhs << ": " << m;
    }
  }
  // An index of ordinary size is still read.
  EXPECT_NO_THROW(parse_user_claim_file(claim_with_rhs("omega[1]"), "wrap.yaml"));
}

}  // namespace
}  // namespace linkproof
