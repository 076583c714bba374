#include "cli.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ostream.h>

#include <charconv>
#include <optional>

#include "dijksman1966.h"
#include "linkproof/eval/check.h"
#include "linkproof/eval/sweep.h"
#include "linkproof/io/scene.h"
#include "linkproof/report/json_report.h"
#include "linkproof/report/text_report.h"

namespace linkproof::cli {

namespace {

struct CheckArgs {
  std::string scene;
  std::string arith = "exact";
  bool json = false;
  bool no_terms = false;
};

struct SweepArgs {
  std::string n_range = "4..12";
  int count = 100;
  std::uint64_t seed = 1;
  std::string arith = "exact";
  std::optional<int> index;
  bool json = false;
};

Arithmetic arithmetic_or_throw(const std::string& s) {
  auto a = parse_arithmetic(s);
  if (!a) throw InputError("<command line>", "--arith", "'" + s + "' is not one of exact, double, long-double");
  return *a;
}

std::pair<int, int> parse_n_range(const std::string& s) {
  const auto bad = [&] {
    return InputError("<command line>", "--n", "'" + s + "' is not N or A..B with 4 <= A <= B <= 200");
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
  if (a < 4 || b < a || b > 200) throw bad();
  return {a, b};
}

int run_check(const CheckArgs& a, std::ostream& out) {
  const Arithmetic arith = arithmetic_or_throw(a.arith);
  const PolygonScene scene = load_polygon_scene(a.scene);
  GroundTruthEngine engine;
  const PolygonCheck check =
      check_polygon(engine, dijksman1966::catalogue(), scene.name, scene.polygon, scene.rates, arith);
  if (a.json)
    out << to_json(check).dump(2) << "\n";
  else
    write_text(out, check, !a.no_terms);
  return exit_status(check);
}

int run_sweep_command(const SweepArgs& a, std::ostream& out) {
  SweepOptions o;
  std::tie(o.n_min, o.n_max) = parse_n_range(a.n_range);
  if (a.count < 1 || a.count > 1000000) throw InputError("<command line>", "--count", "must be between 1 and 1000000");
  if (a.index && *a.index < 0) throw InputError("<command line>", "--index", "must be >= 0");
  o.count = a.count;
  o.seed = a.seed;
  o.arithmetic = arithmetic_or_throw(a.arith);
  o.only_index = a.index;
  GroundTruthEngine engine;
  const SweepReport r = run_sweep(engine, dijksman1966::catalogue(), o);
  if (a.json)
    out << to_json(r).dump(2) << "\n";
  else
    write_text(out, r);
  return r.exit_status();
}

}  // namespace

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"linkproof: checks published kinematics formulas of planar linkages against the exact truth"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "linkproof 0.1.0");

  CheckArgs check;
  auto* c = app.add_subcommand("check", "check every claim on a scene (YAML)");
  c->add_option("scene", check.scene, "scene file, e.g. verify/scenes/pentagon.yaml")->required();
  c->add_option("--arith", check.arith, "arithmetic: exact (default), double, long-double");
  c->add_flag("--json", check.json, "print JSON (the contract in README.md)");
  c->add_flag("--no-terms", check.no_terms, "omit the term-by-term tables from the text report");

  SweepArgs sweep;
  auto* s = app.add_subcommand("sweep", "check every claim on random exact polygons");
  s->add_option("--n", sweep.n_range, "number of sides, N or A..B (default 4..12)");
  s->add_option("--count", sweep.count, "cases per n (default 100)");
  s->add_option("--seed", sweep.seed, "seed; any case replays from seed, n and index (default 1)");
  s->add_option("--arith", sweep.arith, "arithmetic: exact (default), double, long-double");
  s->add_option("--index", sweep.index, "replay only this case index");
  s->add_flag("--json", sweep.json, "print JSON");

  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them reversed
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return kAsExpected;
  } catch (const CLI::CallForVersion&) {
    out << "linkproof 0.1.0\n";
    return kAsExpected;
  } catch (const CLI::ParseError& e) {
    fmt::print(err, "linkproof: {}\n{}", e.what(), app.help());
    return kBadInput;
  }

  try {
    if (c->parsed()) return run_check(check, out);
    if (s->parsed()) return run_sweep_command(sweep, out);
  } catch (const InputError& e) {
    fmt::print(err, "linkproof: bad input: {}\n", e.what());
    return kBadInput;
  } catch (const InternalError& e) {
    fmt::print(err, "linkproof: internal error: {}\n", e.what());
    return kInternalError;
  } catch (const std::exception& e) {
    fmt::print(err, "linkproof: internal error: {}\n", e.what());
    return kInternalError;
  }
  return kInternalError;
}

}  // namespace linkproof::cli
