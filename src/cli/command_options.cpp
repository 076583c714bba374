#include <charconv>
#include <string_view>

#include "command.h"
#include "linkproof/core/error.h"

namespace linkproof::cli {

Arithmetic arithmetic_or_throw(const std::string& s) {
  auto a = parse_arithmetic(s);
  if (!a) throw InputError("<command line>", "--arith", "'" + s + "' is not one of " + arithmetic_names());
  return *a;
}

std::pair<int, int> parse_n_range(const std::string& s, const std::string& option, int lo, int hi) {
  const auto bad = [&] {
    return InputError("<command line>", option,
                      "'" + s + "' is not N or A..B with " + std::to_string(lo) + " <= A <= B <= " + std::to_string(hi));
  };
  const auto number = [&](std::string_view t) {
    int v = 0;
    auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || p != t.data() + t.size()) throw bad();
    return v;
  };
  int a = 0, b = 0;
  if (auto dots = s.find(".."); dots != std::string::npos) {
    a = number(std::string_view(s).substr(0, dots));
    b = number(std::string_view(s).substr(dots + 2));
  } else {
    a = b = number(s);
  }
  if (a < lo || b < a || b > hi) throw bad();
  return {a, b};
}

}  // namespace linkproof::cli
