// linkproof check-data SCENE DATA.csv [--json]
// Recorded motion against the exact truth at the recorded positions (numerics/data_check.h).
#include "command.h"
#include "linkproof/io/mechanism_scene.h"
#include "io/motion_data.h"
#include "numerics/data_check.h"
#include "report/data_check_report.h"
#include "report/scene_placement_report.h"

namespace linkproof::cli {

namespace {

struct CheckDataArgs {
  std::string scene, data;
  bool json = false;
};

int run_check_data(const CheckDataArgs& a, std::ostream& out, std::ostream& err) {
  const MechanismScene scene = load_mechanism_scene(a.scene);
  // A scene given by dimensions runs on rationalised positions: said, never silent.
  if (const std::string note = rationalised_statement(scene); !note.empty())
    err << "linkproof: note: " << a.scene << ": " << note << " (docs/mechanisms.md)\n";
  const MotionData data = load_motion_data(a.data, scene);
  const DataCheck check = check_motion_data(scene, data);
  return print_report(out, check, a.json, exit_status(check));
}

}  // namespace

void add_check_data_command(CLI::App& app, Action& action) {
  auto* c = app.add_subcommand("check-data", "check recorded motion (CSV) against the exact truth at its positions");
  auto& a = bind_action<CheckDataArgs>(c, action, run_check_data);
  c->add_option("scene", a.scene, "mechanism scene: the linkage, its inputs, reference positions")->required();
  c->add_option("data", a.data, "CSV: per sample joint positions, input rates, the user's omega/alpha")->required();
  c->add_flag("--json", a.json, "print JSON (the contract in docs/testing.md)");
}

}  // namespace linkproof::cli
