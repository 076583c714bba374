// linkproof curvature SCENE [--json]
// Poles, path curvature centres, Bobillier's construction and joint-joining reductions of a
// mechanism scene (docs/curvature.md), with their claims, exact.
#include "command.h"
#include "linkproof/io/mechanism_scene.h"
#include "report/curvature_report.h"
#include "report/scene_placement_report.h"
#include "mechanism_catalogues.h"

namespace linkproof::cli {

namespace {

struct CurvatureArgs {
  std::string scene;
  bool json = false;
};

int run_curvature(const CurvatureArgs& a, std::ostream& out, std::ostream& err) {
  const MechanismScene scene = load_mechanism_scene(a.scene);
  // A scene given by dimensions runs on rationalised positions: said, never silent.
  if (const std::string note = rationalised_statement(scene); !note.empty())
    err << "linkproof: note: " << a.scene << ": " << note << " (docs/mechanisms.md)\n";
  const CurvatureCheck check = check_curvature(scene, catalogues::second_order_catalogues(scene));
  // The check's claims under the default policy (curvature has no --strict).
  const ClaimsStatus status = claims_status(check.claims);
  if (a.json)
    out << json_text(to_json(check, status)) << "\n";
  else
    write_text(out, check, status);
  return status.exit_status;
}

}  // namespace

void add_curvature_command(CLI::App& app, Action& action) {
  auto* c = app.add_subcommand("curvature", "poles, curvature centres, Bobillier and joint-joining of a mechanism (docs/conventions.md §D)");
  auto& a = bind_action<CurvatureArgs>(c, action, run_curvature);
  c->add_option("scene", a.scene, "mechanism scene, e.g. verify/scenes/mechanisms/dijksman1984_eightbar.yaml")->required();
  c->add_flag("--json", a.json, "print JSON (docs/curvature.md)");
}

}  // namespace linkproof::cli
