#include "src/network/ccx_connectivity.hpp"

#include <algorithm>
#include <cstdint>
#include <random>

namespace cg::network {
namespace {

// The largest position k (1-based) with list[k] <= value, 0 if none: a binary search that, like
// CalculiX's, trusts the list to be sorted although marked entries are negative.
std::size_t position(const std::vector<int>& list, int value) {
  std::size_t lo = 0, hi = list.size() + 1;
  while (hi - lo > 1) {
    const std::size_t m = (lo + hi) / 2;
    if (value >= list[m - 1])
      lo = m;
    else
      hi = m;
  }
  return lo;
}

struct Walk {
  const std::vector<DeckElement>& elements;
  std::vector<int> list;                      // every node of the deck, sorted; negative = marked
  std::vector<std::vector<std::size_t>> at;   // elements at each node, the last defined first
  std::vector<char> done;                     // element treated

  void mark(int node) {
    const std::size_t k = position(list, node);
    if (k > 0) list[k - 1] = -list[k - 1];
  }
  // From one INOUT element: sweeps over the list, treating every element at a marked node and marking
  // its other end, until a sweep finds no marked node. A sweep restarts at the first node once it
  // meets a node whose last listed element was already treated (as CalculiX's loop does).
  void branch(std::size_t io) {
    done[io] = 1;
    mark(elements[io].first != 0 ? elements[io].first : elements[io].last);
    for (bool marked = true; marked;) {
      marked = false;
      for (std::size_t j = 0; j < list.size(); ++j) {
        if (list[j] > 0) continue;
        marked = true;
        list[j] = -list[j];
        const int node = list[j];
        const std::vector<std::size_t>& els = at[static_cast<std::size_t>(node)];
        bool restart = false;
        for (std::size_t k = 0; k < els.size(); ++k) {
          const std::size_t e = els[k];
          if (done[e]) {
            if (k + 1 == els.size()) restart = true;
            continue;
          }
          done[e] = 1;
          const int other = elements[e].first != node ? elements[e].first : elements[e].last;
          if (other != 0) mark(other);
        }
        if (restart) break;
      }
    }
  }
};

bool is_inout(const DeckElement& d) { return d.first == 0 || d.last == 0; }

// New id of every node (index: old id) for a breadth-first walk from the supplies over the elements.
std::vector<int> breadth_first(const Network& net) {
  std::vector<std::vector<int>> next(net.nodes.size() + 1);
  for (const Element& e : net.elements) {
    next[static_cast<std::size_t>(e.upstream)].push_back(e.downstream);
    next[static_cast<std::size_t>(e.downstream)].push_back(e.upstream);
  }
  std::vector<int> order, id(net.nodes.size() + 1, 0);
  for (const Node& n : net.nodes)
    if (n.kind == NodeKind::Supply) order.push_back(n.id), id[static_cast<std::size_t>(n.id)] = static_cast<int>(order.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    for (int m : next[static_cast<std::size_t>(order[k])])
      if (id[static_cast<std::size_t>(m)] == 0) order.push_back(m), id[static_cast<std::size_t>(m)] = static_cast<int>(order.size());
  for (const Node& n : net.nodes)  // not reachable from a supply: after the rest
    if (id[static_cast<std::size_t>(n.id)] == 0) order.push_back(n.id), id[static_cast<std::size_t>(n.id)] = static_cast<int>(order.size());
  return id;
}

// A permutation of the node ids from a seeded generator (Fisher-Yates; deterministic on every platform).
std::vector<int> shuffled(const Network& net, std::uint32_t seed) {
  std::vector<int> order(net.nodes.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k) + 1;
  std::mt19937 gen(seed);
  for (std::size_t k = order.size(); k > 1; --k) std::swap(order[k - 1], order[gen() % k]);
  std::vector<int> id(net.nodes.size() + 1, 0);
  for (std::size_t k = 0; k < order.size(); ++k) id[static_cast<std::size_t>(order[k])] = static_cast<int>(k) + 1;
  return id;
}

Network renumbered(const Network& net, const std::vector<int>& id) {
  Network out = net;
  for (Node& n : out.nodes) n.id = id[static_cast<std::size_t>(n.id)];
  std::sort(out.nodes.begin(), out.nodes.end(), [](const Node& a, const Node& b) { return a.id < b.id; });
  for (Element& e : out.elements) {
    e.upstream = id[static_cast<std::size_t>(e.upstream)];
    e.downstream = id[static_cast<std::size_t>(e.downstream)];
  }
  return out;
}

}  // namespace

bool ccx_accepts_connectivity(const DeckLayout& layout) {
  Walk w{layout.elements, {}, {}, std::vector<char>(layout.elements.size(), 0)};
  int top = 0;
  for (const DeckElement& d : layout.elements) top = std::max({top, d.first, d.mid, d.last});
  w.at.resize(static_cast<std::size_t>(top) + 1);
  for (std::size_t e = 0; e < layout.elements.size(); ++e)
    for (int node : {layout.elements[e].first, layout.elements[e].mid, layout.elements[e].last})
      if (node != 0) w.at[static_cast<std::size_t>(node)].insert(w.at[static_cast<std::size_t>(node)].begin(), e);
  for (int node = 1; node <= top; ++node)
    if (!w.at[static_cast<std::size_t>(node)].empty()) w.list.push_back(node);
  // One branch per untreated INOUT element, always the first one in element order, until none is left.
  for (;;) {
    std::size_t io = layout.elements.size();
    for (std::size_t e = 0; e < layout.elements.size() && io == layout.elements.size(); ++e)
      if (!w.done[e] && is_inout(layout.elements[e])) io = e;
    if (io == layout.elements.size()) break;
    w.branch(io);
  }
  return std::all_of(w.done.begin(), w.done.end(), [](char d) { return d != 0; });
}

bool number_nodes_for_ccx(Network& net) {
  if (ccx_accepts_connectivity(deck_layout(net))) return true;
  Network candidate = renumbered(net, breadth_first(net));
  for (std::uint32_t seed = 1; !ccx_accepts_connectivity(deck_layout(candidate)); ++seed) {
    if (seed > 32) return false;
    candidate = renumbered(net, shuffled(net, seed));
  }
  net = std::move(candidate);
  return true;
}

}  // namespace cg::network
