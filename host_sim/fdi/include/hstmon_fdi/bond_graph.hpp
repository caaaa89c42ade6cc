#pragma once
/// @file bond_graph.hpp
/// The thesis's bond graph (Fig. 2.3, nonlinear valves; Fig. 2.14, linearised valves) as
/// data: elements and bonds with their half-arrow (power) directions. The figures are not
/// in the seed's text; the structure is reconstructed from equations 2.5–2.8 and the bond
/// numbers of Table 2.4 (docs/fdi.md lists the reconstruction and where it departs).

#include <string>
#include <string_view>
#include <vector>

namespace hstmon::fdi {

/// How the valve orifices (DCV inlet R2, DCV outlet R15, PRV R33) are modelled.
enum class ValveModel {
  kNonlinear,   ///< Fig. 2.3: Q = k·sq(ΔP), parameters kfi, kfo, kp; edge gains are the tangent slopes
  kLinearised,  ///< Fig. 2.14: Q = ΔP/R, parameters Rin, Rout, Rpl of eq. 2.11 (secant R = √ΔP/k)
};

/// Kind of a bond-graph element.
enum class ElementKind { kSe, kR, kC, kI, kTF, kZero, kOne, kDetector, kSf };

/// One element: a source, a storage, a resistance, a transformer, a junction or a sensor.
struct Element {
  std::string name;       ///< "R33", "C4", "TF7/8", "0_mi", "De5"
  ElementKind kind;
  std::string parameter;  ///< parameter name ("Rpl", "Kpmi", "Dm"); empty for junctions
  std::string meaning;    ///< what it stands for in the rig
};

/// One bond: its number (Table 2.4) and its half-arrow, power positive from → to.
struct Bond {
  int number;        ///< bond number, 1…35
  std::string from;  ///< element the half-arrow leaves
  std::string to;    ///< element the half-arrow points at
};

/// A bond graph: elements and bonds.
struct BondGraph {
  std::vector<Element> elements;
  std::vector<Bond> bonds;

  /// Element by name, or nullptr.
  const Element* element(std::string_view name) const;
  /// Bond by number, or nullptr.
  const Bond* bond(int number) const;
  /// +1 if the bond points into element `name`, −1 if it leaves it, 0 if not attached.
  int orientation(int bond_number, std::string_view name) const;
};

/// The thesis HST's bond graph with the given valve model.
BondGraph thesis_bond_graph(ValveModel valves);

}  // namespace hstmon::fdi
