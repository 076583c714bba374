// Koshel et al. (docs/conventions.md §C) as data, verify/claims/mechanisms/koshel_class3.yaml: on
// the bundled scene every data claim gives the verdict, and the exact values, of the C++ catalogue
// claim it mirrors (verify/catalogue/koshel_class3.cpp). The C++ claims re-solve the linkage (rocker
// 5 driving, a trial epsilon5); the data claims build the same plan dyad by dyad, as the paper
// draws it, so equal values mean the construction and the solver agree exactly.
#include "data_mirror.h"
#include "mechanism_catalogues.h"

namespace linkproof {
namespace {

using testing_mirror::Mirror;

TEST(KoshelClass3Data, EveryDataClaimMatchesTheCatalogueClaimItMirrorsExactly) {
  std::vector<Mirror> mirrors;
  for (const char* i : {"1", "2", "3", "6"})
    mirrors.push_back({std::string("koshel.driver5.epsilon") + i, "koshel.driver5", std::string("epsilon[") + i + "]"});
  // eqs. (16)-(19): epsilon2, 3, 5, 6 (the catalogue also compares the crank's and the sliders').
  for (const char* i : {"2", "3", "5", "6"}) {
    mirrors.push_back({std::string("koshel.eq15.rescaled_epsilon") + i, "koshel.eq15.rescaling",
                       std::string("epsilon[") + i + "]^2"});
    mirrors.push_back({std::string("koshel.superposition.epsilon") + i, "koshel.eq15.superposition",
                       std::string("epsilon[") + i + "]"});
  }
  // The catalogue re-solves the inversions; the data states the prismatic pair's relation seen
  // from link 3 (docs/conventions.md §C): the same verdicts, other values.
  mirrors.push_back({"koshel.prismatic_pair.coriolis", "koshel.coriolis.inversion", ""});
  mirrors.push_back({"koshel.prismatic_pair.coriolis_dropped", "koshel.coriolis.dropped", ""});
  testing_mirror::expect_mirrored(catalogues::koshel_class3().claims, "verify/claims/mechanisms/koshel_class3.yaml",
                                  "verify/scenes/mechanisms/seed003_class3.yaml", mirrors);
}

}  // namespace
}  // namespace linkproof
