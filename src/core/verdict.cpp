#include "linkproof/core/verdict.h"

namespace linkproof {

std::string_view to_string(Verdict v) {
  switch (v) {
    case Verdict::Holds: return "holds";
    case Verdict::Fails: return "fails";
    case Verdict::Undefined: return "undefined";
    case Verdict::Inconclusive: return "inconclusive";
    case Verdict::Error: return "error";
  }
  return "error";
}

namespace {
int severity(Verdict v) {
  switch (v) {
    case Verdict::Fails: return 4;
    case Verdict::Error: return 3;
    case Verdict::Undefined: return 2;
    case Verdict::Inconclusive: return 1;
    case Verdict::Holds: return 0;
  }
  return 3;
}
}  // namespace

Verdict combine(Verdict a, Verdict b) { return severity(a) >= severity(b) ? a : b; }

std::string_view to_string(Expectation e) { return e == Expectation::Holds ? "holds" : "fails"; }

}  // namespace linkproof
