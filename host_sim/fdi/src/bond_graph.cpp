/// @file bond_graph.cpp
#include "hstmon_fdi/bond_graph.hpp"

namespace hstmon::fdi {

const Element* BondGraph::element(std::string_view name) const {
  for (const Element& e : elements) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

const Bond* BondGraph::bond(int number) const {
  for (const Bond& b : bonds) {
    if (b.number == number) return &b;
  }
  return nullptr;
}

int BondGraph::orientation(int bond_number, std::string_view name) const {
  const Bond* b = bond(bond_number);
  if (b == nullptr) return 0;
  if (b->to == name) return 1;
  if (b->from == name) return -1;
  return 0;
}

}  // namespace hstmon::fdi
