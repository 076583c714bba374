// Slots in reports (MechanismCheck::slots, docs/mechanisms.md "Slots"): a pin in a straight slot is
// one joint to its reader, though the engine solves it as a prismatic pair P [slotted, P.block]
// and a revolute pair P.pin [P.block, pin link]. Reports show P as the slot (with its sliding
// rates and Coriolis term) and leave out the row of the block link and of the pin joint, which
// would repeat P's point and the slotted link's rates. JSON keeps them (report/mechanism_report.h).
#pragma once

#include <algorithm>
#include <string>

#include "linkproof/mechanism/mechanism_check.h"

namespace linkproof {

/// The slot whose prismatic pair is joint `name`, or null.
inline const MechanismCheck::Slot* slot_of_joint(const MechanismCheck& c, const std::string& name) {
  const auto it = std::find_if(c.slots.begin(), c.slots.end(), [&](const auto& s) { return s.joint == name; });
  return it == c.slots.end() ? nullptr : &*it;
}

/// True for a slot's block link or pin joint: rows the reports leave out.
inline bool is_hidden_slot_part(const MechanismCheck& c, const std::string& name) {
  return std::any_of(c.slots.begin(), c.slots.end(), [&](const auto& s) { return s.block == name || s.pin == name; });
}

/// True for joint `name` of `g` that is a slot's pin P.pin (a joint P and a link P.block exist;
/// io/mechanism_scene.h refuses those names otherwise): for reports made from the scene alone.
inline bool is_slot_pin_joint(const Linkage& g, const std::string& name) {
  if (name.size() <= 4 || !name.ends_with(".pin")) return false;
  const std::string slot = name.substr(0, name.size() - 4);
  return g.find_joint(slot).has_value() && g.find_link(slot + ".block").has_value();
}

/// "pin of crank in a slot of wheel".
inline std::string slot_description(const MechanismCheck::Slot& s) {
  return "pin of " + s.pin_link + " in a slot of " + s.slotted;
}

}  // namespace linkproof
