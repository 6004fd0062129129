#pragma once
// The network as a CalculiX input deck (network.inp; element types and units in docs/network.md and
// ../shared notes): units N-mm-s-tonne-K (pressures MPa, mass flow t/s); its element and node numbers
// are ccx_layout.hpp's (the deck's comment lines say which is which).
#include <string>
#include <vector>

#include "src/network/network_model.hpp"

namespace cg::network {

/// The deck's text.
std::string ccx_deck(const Network& net);

/// The initial total pressure (Pa) of every node, in node order: an incompressible solution of the
/// network (orifices Cd 0.65, segments lambda 0.02, bends K 1.5, at the supply's density), then made to
/// fall strictly (1e-6 of the supply) along every element into a junction (CalculiX needs falling
/// guesses at nodes with more than two elements; a crude guess took 60-200 iterations or failed).
std::vector<double> initial_pressures(const Network& net);

/// Mid node of element `id` in the deck.
inline int mid_node(const Network& net, int element_id) { return static_cast<int>(net.nodes.size()) + element_id; }

}  // namespace cg::network
