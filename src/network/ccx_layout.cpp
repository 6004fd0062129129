#include "src/network/ccx_layout.hpp"

namespace cg::network {

DeckLayout deck_layout(const Network& net) {
  DeckLayout l;
  const int nn = static_cast<int>(net.nodes.size()), ne = static_cast<int>(net.elements.size());
  for (const Node& n : net.nodes)
    if (n.kind == NodeKind::Supply) l.supplies.push_back(n.id);
  for (const Element& e : net.elements)
    if (net.node(e.downstream).kind == NodeKind::Sink) l.exits.push_back(e.id);
  const int n_io = static_cast<int>(l.supplies.size() + l.exits.size());
  const int copy_base = nn + ne + n_io;
  for (std::size_t k = 0; k < l.exits.size(); ++k) l.exit_nodes.push_back(copy_base + static_cast<int>(k) + 1);
  for (const Element& e : net.elements) l.elements.push_back({e.id, e.upstream, nn + e.id, e.downstream});
  for (std::size_t k = 0; k < l.exits.size(); ++k) l.elements[static_cast<std::size_t>(l.exits[k] - 1)].last = l.exit_nodes[k];
  l.first_inout = ne + 1;
  int io = ne;
  for (int node : l.supplies) ++io, l.elements.push_back({io, 0, nn + io, node});
  for (int node : l.exit_nodes) ++io, l.elements.push_back({io, node, nn + io, 0});
  return l;
}

}  // namespace cg::network
