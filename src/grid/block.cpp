#include "src/grid/block.hpp"

#include <algorithm>

#include "src/core/error.hpp"

namespace cg::grid {

Block::Block(std::string n, int ni_, int nj_) : name(std::move(n)), ni(ni_), nj(nj_) {
  require(ni >= 1 && nj >= 1, "grid block " + name + ": needs at least one cell in each direction");
  nodes.assign(static_cast<std::size_t>((ni + 1) * (nj + 1)), Eigen::Vector2d::Zero());
}

Eigen::Vector2i face_node(const Block& b, const FaceRange& r, int k) {
  const int t = r.node(k);
  switch (r.face) {
    case Face::IMin: return {0, t};
    case Face::IMax: return {b.ni, t};
    case Face::JMin: return {t, 0};
    case Face::JMax: return {t, b.nj};
  }
  return {0, 0};
}

const char* boundary_kind_name(BoundaryKind k) {
  switch (k) {
    case BoundaryKind::Wall: return "wall";
    case BoundaryKind::Inlet: return "inlet";
    case BoundaryKind::Outlet: return "outlet";
    case BoundaryKind::Farfield: return "farfield";
  }
  return "?";
}

int MultiBlockGrid::cells() const {
  int n = 0;
  for (const Block& b : blocks) n += b.cells();
  return n;
}

int MultiBlockGrid::nodes() const {
  int n = 0;
  for (const Block& b : blocks) n += static_cast<int>(b.nodes.size());
  return n;
}

double connection_mismatch(const MultiBlockGrid& g, const Connection& c) {
  const Block& a = g.blocks[static_cast<std::size_t>(c.block)];
  const Block& d = g.blocks[static_cast<std::size_t>(c.donor)];
  require(c.range.nodes() == c.donor_range.nodes(), "connection " + c.name + ": node counts differ");
  double worst = 0;
  for (int k = 0; k < c.range.nodes(); ++k) {
    const Eigen::Vector2i p = face_node(a, c.range, k), q = face_node(d, c.donor_range, k);
    worst = std::max(worst, (a.at(p.x(), p.y()) + c.translation - d.at(q.x(), q.y())).norm());
  }
  return worst;
}

namespace {

void reverse_range(FaceRange& r, const Block& b) {
  if (r.face == Face::IMin || r.face == Face::IMax) {
    r.face = r.face == Face::IMin ? Face::IMax : Face::IMin;
  } else {
    r.begin = b.ni - r.begin;
    r.end = b.ni - r.end;
  }
}

}  // namespace

void reverse_i(MultiBlockGrid& g, int index) {
  Block& b = g.blocks[static_cast<std::size_t>(index)];
  for (int j = 0; j <= b.nj; ++j)
    std::reverse(b.nodes.begin() + j * (b.ni + 1), b.nodes.begin() + (j + 1) * (b.ni + 1));
  for (BoundaryCondition& bc : g.boundaries)
    if (bc.block == index) reverse_range(bc.range, b);
  for (Connection& c : g.connections) {
    if (c.block == index) reverse_range(c.range, b);
    if (c.donor == index) reverse_range(c.donor_range, b);
  }
}

}  // namespace cg::grid
