// linkproof as an oracle in other projects' property tests (docs/testing.md):
//   generators     RapidCheck generators of exact polygons and mechanisms by family, with bias
//                  toward the hard places and shrinking in mechanism space (testing/generators.h)
//   truth          every link's omega and alpha, exact and in double with a rigorous bound
//                  (testing/truth.h)
//   matchers       AngularAccelerationsMatch, ClaimHolds (testing/matchers.h)
//   oracle         rc_assert_alpha_matches: one line in an RC_GTEST_PROP (testing/oracle.h)
//
//   find_package(linkproof 0.1 REQUIRED COMPONENTS testing)
//   target_link_libraries(my_tests PRIVATE linkproof::testing)   # brings RapidCheck and GTest/GMock
#pragma once

#include "linkproof/testing/cases.h"
#include "linkproof/testing/claim_result.h"
#include "linkproof/testing/compare.h"
#include "linkproof/testing/generators.h"
#include "linkproof/testing/matchers.h"
#include "linkproof/testing/oracle.h"
#include "linkproof/testing/truth.h"
