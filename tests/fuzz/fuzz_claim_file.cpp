// libFuzzer target: the claim-file reader (io/claim_file.h) and the claim expression parser
// (claims/claim_expression.h) on the raw bytes. Any bytes must give a result or an InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "claims/claim_expression.h"
#include "linkproof/core/error.h"
#include "io/claim_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)linkproof::parse_claim_file(text, "fuzz.yaml");
  } catch (const linkproof::InputError&) {
  }
  try {
    (void)linkproof::ClaimExpression::parse(text, linkproof::ExpressionContext{"fuzz", "expression", true});
  } catch (const linkproof::InputError&) {
  }
  return 0;
}
