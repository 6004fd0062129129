#pragma once
// How the network is laid out in CalculiX's deck (network.inp): the numbers of every deck element and
// node, shared by the deck writer (ccx_deck.hpp) and the model of CalculiX's connectivity check
// (ccx_connectivity.hpp). Corner nodes are the network's node ids; the mid node of element e is
// nodes + e; each supply gets an INOUT element from the outside (node 0) and each exit its own copy of
// its sink node with an INOUT element to the outside, numbered after the network's elements.
#include <vector>

#include "src/network/network_model.hpp"

namespace cg::network {

/// One deck element: "id, first, mid, last" (0 = the outside).
struct DeckElement {
  int id = 0, first = 0, mid = 0, last = 0;
};

struct DeckLayout {
  std::vector<int> supplies;           ///< supply node ids, in node order
  std::vector<int> exits;              ///< ids of the elements that end in a sink, in element order
  std::vector<int> exit_nodes;         ///< exit k's copy of its sink
  std::vector<DeckElement> elements;   ///< the network's elements (ids 1..; an exit ends in its sink copy), then the INOUT elements
  int first_inout = 0;                 ///< id of the first INOUT element
};

DeckLayout deck_layout(const Network& net);

}  // namespace cg::network
