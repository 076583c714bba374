#include "claims/claim.h"

#include "linkproof/core/error.h"

namespace linkproof {

void refuse_if_ill_formed_user_claim(const ClaimInfo& info, const std::exception& e) {
  if (const auto* bad = dynamic_cast<const InputError*>(&e); bad && !info.file.empty())
    throw InputError(info.file, "claim '" + info.id + "'", bad->problem());
}

}  // namespace linkproof
