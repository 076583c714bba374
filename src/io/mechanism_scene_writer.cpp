// mechanism_scene_to_yaml: the inverse of the mechanism scene reader (io/mechanism_scene.h).
#include <yaml-cpp/yaml.h>

#include "linkproof/core/error.h"
#include "linkproof/io/mechanism_scene.h"
#include "scene_ask.h"
#include "yaml_document.h"

namespace linkproof {

namespace {

void emit_point(YAML::Emitter& out, const Vec2<Rational>& p) {
  out << YAML::Flow << YAML::BeginSeq;
  yaml_io::emit_number(out, p.x);
  yaml_io::emit_number(out, p.y);
  out << YAML::EndSeq;
}

void emit_joint(YAML::Emitter& out, const Linkage& g, const LinkageJoint& j) {
  out << YAML::Flow << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << YAML::DoubleQuoted << j.name;
  out << YAML::Key << "type" << YAML::Value << (j.type == JointType::Prismatic ? "prismatic" : "revolute");
  out << YAML::Key << "links" << YAML::Value << YAML::Flow << YAML::BeginSeq << YAML::DoubleQuoted
      << g.link_name(j.links[0]) << YAML::DoubleQuoted << g.link_name(j.links[1]) << YAML::EndSeq;
  out << YAML::Key << "at" << YAML::Value;
  emit_point(out, j.at);
  if (j.type == JointType::Prismatic) {
    out << YAML::Key << "axis" << YAML::Value;
    emit_point(out, j.axis);
  }
  out << YAML::EndMap;
}

void emit_input(YAML::Emitter& out, const Linkage& g, const MechanismInput& in) {
  const bool link = in.kind == MechanismInput::Kind::Link;
  out << YAML::Flow << YAML::BeginMap;
  if (link)
    out << YAML::Key << "link" << YAML::Value << YAML::DoubleQuoted << g.link_name(in.index);
  else
    out << YAML::Key << "joint" << YAML::Value << YAML::DoubleQuoted << g.joint(in.index).name;
  out << YAML::Key << (link ? "omega" : "v") << YAML::Value;
  yaml_io::emit_number(out, in.rate);
  out << YAML::Key << (link ? "omega_dot" : "a") << YAML::Value;
  yaml_io::emit_number(out, in.rate_dot);
  out << YAML::EndMap;
}

}  // namespace

std::string mechanism_scene_to_yaml(const MechanismScene& scene) {
  const Linkage& g = scene.linkage;
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << YAML::DoubleQuoted << scene.name;
  out << YAML::Key << "mechanism" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "ground" << YAML::Value << YAML::DoubleQuoted << g.link_name(g.ground());
  out << YAML::Key << "links" << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (const auto& name : g.link_names()) out << YAML::DoubleQuoted << name;
  out << YAML::EndSeq;
  out << YAML::Key << "joints" << YAML::Value << YAML::BeginSeq;
  for (const auto& j : g.joints()) emit_joint(out, g, j);
  out << YAML::EndSeq;
  out << YAML::Key << "inputs" << YAML::Value << YAML::BeginSeq;
  for (const auto& in : scene.inputs) emit_input(out, g, in);
  out << YAML::EndSeq;
  if (!scene.points.empty()) {
    out << YAML::Key << "points" << YAML::Value << YAML::BeginSeq;
    for (const auto& p : scene.points) {
      out << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << YAML::DoubleQuoted << p.name;
      out << YAML::Key << "link" << YAML::Value << YAML::DoubleQuoted << g.link_name(p.link);
      out << YAML::Key << "at" << YAML::Value;
      emit_point(out, p.at);
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }
  if (!scene.dimensions.empty()) {
    out << YAML::Key << "dimensions" << YAML::Value << YAML::BeginSeq;
    for (const auto& d : scene.dimensions) {
      out << YAML::Flow << YAML::BeginMap << YAML::Key << "joints" << YAML::Value << YAML::Flow << YAML::BeginSeq
          << YAML::DoubleQuoted << g.joint(d.joint_a).name << YAML::DoubleQuoted << g.joint(d.joint_b).name
          << YAML::EndSeq << YAML::Key << "length" << YAML::Value;
      yaml_io::emit_number(out, d.length);
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }
  if (scene.tolerance) {
    out << YAML::Key << "tolerance" << YAML::Value;
    yaml_io::emit_number(out, *scene.tolerance);
  }
  if (!scene.catalogues.empty()) {
    out << YAML::Key << "catalogue" << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (const auto& c : scene.catalogues) out << c;
    out << YAML::EndSeq;
  }
  out << YAML::EndMap;
  if (scene.ask) yaml_io::emit_ask(out, *scene.ask);
  out << YAML::EndMap;
  LINKPROOF_ASSERT(out.good(), "YAML emitter failed: " + out.GetLastError());
  return std::string(out.c_str()) + "\n";
}

}  // namespace linkproof
