#pragma once
// CalculiX 2.20 checks, before it solves, that every network element is reachable from an input/output
// element (its routine checkforhomnet). The check walks the network from each INOUT element, marking
// nodes by flipping their sign in the sorted list of the deck's nodes and finding them there by binary
// search: once several marked (negative) nodes sit in the list, the search can miss a node or flip
// another one, and the check then refuses a connected network ("network elements not connected to an
// input/output element", exit 201) depending only on how the nodes are numbered. The built-in example
// with its 18 pin banks in front of the slots is such a case in the builder's numbering.
//
// This module replays that walk on the deck's layout (ccx_layout.hpp), so the network can be numbered
// so that CalculiX accepts it: nodes in breadth-first order from the supply (the walk then marks nodes
// in increasing order, which the binary search finds), or other orders when that one is refused.
#include "src/network/ccx_layout.hpp"

namespace cg::network {

/// Whether CalculiX 2.20's connectivity check accepts this deck layout (a replay of its walk).
bool ccx_accepts_connectivity(const DeckLayout& layout);

/// Renumbers the network's nodes (elements keep their ids and order) so that CalculiX's connectivity
/// check accepts its deck: the present numbering if it passes, else breadth-first from the supplies,
/// else seeded permutations of the junctions (at most 32 tried). False when none passed (the numbering
/// is then left as it was and CalculiX will refuse the deck: the solve reports it as not converged).
bool number_nodes_for_ccx(Network& net);

}  // namespace cg::network
