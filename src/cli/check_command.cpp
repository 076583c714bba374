// linkproof check SCENE [--arith exact|double|long-double|mp30|mp50|mp100|mp1000] [--json] [--no-terms]
// SCENE is a polygon scene (io/scene.h) or a mechanism scene (io/mechanism_scene.h).
#include "command.h"
#include "dijksman1966.h"
#include "check/check_polygon.h"
#include "linkproof/io/mechanism_scene.h"
#include "linkproof/io/scene.h"
#include "report/curvature_report.h"
#include "report/mechanism_report.h"
#include "report/scene_placement_report.h"
#include "mechanism_catalogues.h"
#include "report/json_report.h"
#include "report/text_report.h"

namespace linkproof::cli {

namespace {

/// The largest polygon `check` accepts, as `sweep --n` (docs/limits.md): the exact check of every
/// claim takes about 1.6 s at n = 100 and 6 s at n = 200. The reader itself allows
/// kMaxSceneJoints.
constexpr int kMaxCheckSides = 200;

struct CheckArgs {
  std::string scene;
  std::optional<std::string> arith;  // default: the scene's ask, else exact
  bool json = false;
  bool no_terms = false;
  std::optional<int> digits;  // significant digits of the decimals beside exact values (text only)
  bool strict = false;
};

// A mechanism scene (top-level `mechanism:`): the mechanism engine and the scene's catalogues.
int run_mechanism_check(const CheckArgs& a, const std::string& text, std::ostream& out) {
  const MechanismScene scene = parse_mechanism_scene(text, a.scene);
  // An option that does not apply is refused, never ignored: a mechanism's report has no term tables.
  if (a.no_terms)
    throw InputError("<command line>", "--no-terms",
                     "applies to polygon scenes only (a mechanism check prints no term-by-term tables): " + a.scene);
  MechanismCheck check = check_mechanism(scene, catalogues::mechanism_catalogues(scene), chosen_arithmetic(a.arith, scene.ask));
  // Positions placed from dimensions: which are exact, which rationalised (never silent, whatever
  // the arithmetic): JSON keys beside the check's, and a section before the text report.
  // With an ask, only what it names (the second-order work is the `curvature` command's then).
  if ((scene.curvature.empty() && scene.joint_joining.empty()) || check.ask) {
    const ClaimsStatus status = claims_status(check.claims, a.strict);
    if (a.json) {
      nlohmann::json j = to_json(check, status);
      j.update(scene_placement_json(scene));
      out << json_text(j) << "\n";
    } else {
      write_scene_placement_text(out, scene, check.dimensioned ? &*check.dimensioned : nullptr);
      write_text(out, check, status, a.digits.value_or(kReadableDigits));
    }
    return status.exit_status;
  }
  // The scene asks for the second-order work (docs/curvature.md): its claims join the check's,
  // its poles, centres and reductions are added to the report.
  const CurvatureCheck second = check_curvature(scene, {});
  check.claims.insert(check.claims.end(), second.claims.begin(), second.claims.end());
  check.not_applicable.insert(check.not_applicable.end(), second.not_applicable.begin(), second.not_applicable.end());
  const ClaimsStatus status = claims_status(check.claims, a.strict);
  if (a.json) {
    nlohmann::json j = to_json(check, status);
    j.update(curvature_json(*second.analysis, second.link_names));
    j.update(scene_placement_json(scene));
    out << j.dump(2) << "\n";
  } else {
    write_scene_placement_text(out, scene, check.dimensioned ? &*check.dimensioned : nullptr);
    write_text(out, check, status, a.digits.value_or(kReadableDigits));
    write_curvature_text(out, *second.analysis, second.link_names);
  }
  return status.exit_status;
}

int run_check(const CheckArgs& a, std::ostream& out, std::ostream&) {
  if (a.arith) arithmetic_or_throw(*a.arith);  // a bad option is named before the file is read
  if (a.digits && a.json)
    throw InputError("<command line>", "--digits",
                     "applies to the text report (JSON keeps every exact value as p/q): drop --json or --digits");
  // The file is read once (a pipe such as /dev/stdin can be read only once) and its text parsed.
  const std::string text = read_scene_text(a.scene);
  if (is_mechanism_scene_text(text)) return run_mechanism_check(a, text, out);
  const PolygonScene scene = parse_polygon_scene(text, a.scene);
  if (scene.polygon.n() > kMaxCheckSides)
    throw InputError(a.scene, "polygon.joints",
                     "check accepts at most " + std::to_string(kMaxCheckSides) + " joints (as sweep --n; "
                     "docs/limits.md), got " + std::to_string(scene.polygon.n()));
  GroundTruthEngine engine;
  PolygonCheck check = check_polygon(engine, asked_claims(dijksman1966::catalogue(), scene.ask, a.scene), scene.name,
                                     scene.polygon, scene.rates, chosen_arithmetic(a.arith, scene.ask), Evidence::All,
                                     scene.ask);
  const ClaimsStatus status = claims_status(check.claims, a.strict);
  if (a.json)
    out << json_text(to_json(check, status)) << "\n";
  else
    write_text(out, check, status, !a.no_terms, a.digits.value_or(kReadableDigits));
  return status.exit_status;
}

}  // namespace

void add_check_command(CLI::App& app, Action& action) {
  auto* c = app.add_subcommand("check", "check every claim on a scene (YAML)");
  auto& a = bind_action<CheckArgs>(c, action, run_check);
  c->add_option("scene", a.scene, "scene file, e.g. verify/scenes/pentagon.yaml")->required();
  c->add_option("--arith", a.arith,
                "arithmetic: exact (default: rationals, in machine words while they fit and CLN past them; a residual is 0 or not), or floating point with a "
                "running error bound that draws the tolerance: double, long-double, mp30, mp50, mp100, mp1000 "
                "(CLN long floats of 128, 192, 384, 3392 bits); default: the scene's `ask: [arithmetic: ...]`, else exact");
  c->add_flag("--json", a.json, "print JSON (the contract: docs/check.md, docs/mechanisms.md)");
  c->add_option("--digits", a.digits,
                "significant digits of the decimal shown beside each exact value in the text report (default 10)")
      ->check(int_range_validator(1, 100));
  c->add_flag("--no-terms", a.no_terms, "omit the term-by-term tables from the text report (polygon scenes; refused on a mechanism scene)");
  c->add_flag("--strict", a.strict,
              "undefined or inconclusive on a true claim is not as expected (exit 1): for CI");
}

}  // namespace linkproof::cli
