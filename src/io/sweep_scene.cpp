#include "io/sweep_scene.h"

#include <fmt/format.h>

#include "linkproof/io/scene.h"

namespace linkproof {

std::string sweep_scene_name(const RandomPolygonCase& rc) {
  return fmt::format("sweep-seed{}-n{}-i{}", rc.seed, rc.n, rc.index);
}

std::string sweep_scene_yaml(const RandomPolygonCase& rc) {
  PolygonScene s;
  s.name = sweep_scene_name(rc);
  s.polygon = rc.polygon;
  s.rates = rc.rates;
  return polygon_scene_to_yaml(s);
}

}  // namespace linkproof
