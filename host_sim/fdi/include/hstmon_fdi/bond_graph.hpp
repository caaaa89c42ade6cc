#pragma once
/// @file bond_graph.hpp
/// A bond graph as data: elements and bonds with their half-arrow (power) directions.
/// circuit_bond_graph.hpp derives one from any circuit file.

#include <string>
#include <string_view>
#include <vector>

namespace hstmon::fdi {

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

}  // namespace hstmon::fdi
