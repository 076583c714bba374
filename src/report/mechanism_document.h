// The derivation report of a mechanism scene (any planar linkage of revolute and prismatic
// pairs; docs/conventions.md §A7, §B, §C, §E), in this order:
//   summary     the linkage drawn to scale (links as bars or plates, joints, sliders with their
//               guides, tracer points) beside the headline (the asked values, the mobility, the
//               claims at a glance); then mobility, loops, each claim with its verdict and what
//               it rests on (exact);
//   mechanism   the velocities and the accelerations of every joint and point drawn to scale as
//               arrows on the linkage, and the exact omega, omega-dot of every link and the
//               velocity and acceleration of every joint and point, each with its decimal;
//   plans       (when asked) the velocity and acceleration plans: the image of every joint
//               drawn from the origin o, each link's image joining its joints' images; for a
//               four-bar also its acceleration polygon, head to tail as the
//               acceleration-polygon course notes draw it (docs/conventions.md §B);
//   tables      the catalogues' tables (acceleration-polygon vectors, curvature centres, ...);
//   terms, errata, reproduce as in the polygon report.
#pragma once

#include <string>

#include "mechanism/mechanism_catalogue.h"
#include "report/document.h"

namespace linkproof::report {

struct MechanismReportOptions {
  bool plans = false;        ///< add the velocity and acceleration plans
  std::string scene_text;    ///< the scene file's text, shown as the counterexample of failing errata
};

Document build_mechanism_document(const MechanismScene& scene, const MechanismCheck& check,
                                  const MechanismReportOptions& options);

/// The linkage to scale: links, joints, sliders and guides, tracer points.
Drawing mechanism_drawing(const MechanismScene& scene);

}  // namespace linkproof::report
