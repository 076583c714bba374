// Dijksman (1984) (docs/conventions.md §D) as data, verify/claims/mechanisms/dijksman1984_eightbar.yaml:
// on the bundled eight-bar every data claim gives the verdict, and the exact points, of the C++
// catalogue claim it mirrors (verify/catalogue/dijksman1984_eightbar.cpp): the section-3 poles,
// the relocation formulas (1')-(7'') against the curvature centres, and the two errata.
#include "data_mirror.h"
#include "mechanism_catalogues.h"

namespace linkproof {
namespace {

using testing_mirror::Mirror;

TEST(Dijksman1984Data, EveryDataClaimMatchesTheCatalogueClaimItMirrorsExactly) {
  const std::string poles = "dijksman1984.section3.poles";
  std::vector<Mirror> mirrors = {
      {"dijksman1984.section3.P60", poles, "P60 = (67-70) x (63'-3'0)"},
      {"dijksman1984.section3.P64", poles, "P64 = (60-04) x (65-54)"},
      {"dijksman1984.section3.P20", poles, "P20 = (21-10) x (26-60)"},
      {"dijksman1984.section3.P24", poles, "P24 = (23-34) x (20-04)"},
      {"dijksman1984.section3.P60.printed", "dijksman1984.section3.P60.printed", "P60 printed (67-70) x (63''-3''0)"},
      {"dijksman1984.eq5p.printed", "dijksman1984.eq5p.printed", "(5'): relocated 45 vs centre of I57 in 6/4"},
  };
  // (eq, far joint, double joint, t/x), as the catalogue labels them.
  const char* formulas[][4] = {{"(1')", "01", "13", "2/0"},  {"(3')", "34", "13", "2/4"},  {"(5')", "45", "57", "6/4"},
                               {"(7')", "70", "57", "6/0"},  {"(1'')", "12", "17", "0/2"}, {"(3'')", "23", "35", "4/2"},
                               {"(5'')", "56", "35", "4/6"}, {"(7'')", "67", "17", "0/6"}};
  for (const auto& f : formulas) {
    std::string tag;
    for (const char* c = f[0]; *c; ++c)
      if (*c != '(' && *c != ')') tag += *c == '\'' ? 'p' : *c;
    mirrors.push_back({"dijksman1984.eq" + tag, "dijksman1984.eq" + tag,
                       std::string(f[0]) + ": relocated " + f[1] + " vs centre of I" + f[2] + " in " + f[3]});
  }
  testing_mirror::expect_mirrored(catalogues::dijksman1984_eightbar().claims,
                                  "verify/claims/mechanisms/dijksman1984_eightbar.yaml",
                                  "verify/scenes/mechanisms/dijksman1984_eightbar.yaml", mirrors);
}

}  // namespace
}  // namespace linkproof
