#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "command.h"
#include "linkproof/core/error.h"

namespace linkproof::cli {

Arithmetic arithmetic_or_throw(const std::string& s) {
  auto a = parse_arithmetic(s);
  if (!a) throw InputError("<command line>", "--arith", "'" + s + "' is not one of " + arithmetic_names());
  return *a;
}

Arithmetic chosen_arithmetic(const std::optional<std::string>& option, const std::optional<SceneAsk>& ask) {
  if (option) return arithmetic_or_throw(*option);
  if (ask && ask->arithmetic) return *ask->arithmetic;
  return Arithmetic::Exact;
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

namespace {

// The whole of `s` read by from_chars as a T, or nullopt.
template <class T>
std::optional<T> whole_number(const std::string& s) {
  T v{};
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || p != s.data() + s.size()) return std::nullopt;
  return v;
}

}  // namespace

void rethrow_naming_option(const InputError& e, const OptionNames& names) {
  for (const auto& [field, option] : names)
    if (e.field() == field) throw InputError(e.source() == "<api>" ? "<command line>" : e.source(), option, e.problem());
  throw;
}

CLI::Validator seed_validator() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        if (s.empty() || s.front() == '-' || s.front() == '+' || !whole_number<std::uint64_t>(s))
          return "'" + s + "' is not a seed: expected an integer from 0 to 18446744073709551615 (2^64 - 1)";
        return "";
      },
      "SEED");
}

CLI::Validator seconds_validator(double max_seconds) {
  return CLI::Validator(
      [max_seconds](std::string& s) -> std::string {
        const auto v = whole_number<double>(s);
        if (!v || !std::isfinite(*v) || *v < 0 || *v > max_seconds)
          return fmt::format("'{}' is not a time budget: expected a finite number of seconds from 0 to {}", s,
                             max_seconds);
        return "";
      },
      "SECONDS");
}

CLI::Validator int_range_validator(int lo, int hi) {
  return CLI::Validator(
      [lo, hi](std::string& s) -> std::string {
        const auto v = whole_number<int>(s);
        if (!v || *v < lo || *v > hi)
          return "'" + s + "' is not an integer from " + std::to_string(lo) + " to " + std::to_string(hi);
        return "";
      },
      "INT in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

}  // namespace linkproof::cli
