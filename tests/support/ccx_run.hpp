#pragma once
// A CalculiX network deck read and run by tests with readers that are not the product's: the deck's
// connectivity from its *ELEMENT cards (names from its comment lines), and `ccx` run on a copy of it,
// its .dat parsed.
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "brep/temp_files.hpp"

namespace cg::test {

/// network.inp as CalculiX reads it: element connectivity (upstream, mid, downstream) and the
/// *FLUID SECTION type of each element, element names from the deck's comment lines.
struct DeckRead {
  std::map<int, std::array<int, 3>> elements;
  std::map<int, std::string> type, name;
};

inline DeckRead read_deck(const std::string& text) {
  DeckRead d;
  std::istringstream in(text);
  std::string line, elset;
  std::map<std::string, std::vector<int>> sets;
  bool element_block = false;
  while (std::getline(in, line)) {
    if (line.rfind("** element ", 0) == 0) {
      std::istringstream ls(line.substr(11));
      int id = 0;
      std::string n;
      ls >> id >> n;
      d.name[id] = n;
      continue;
    }
    if (line.rfind("**", 0) == 0) continue;
    if (line.rfind("*", 0) == 0) {
      element_block = line.rfind("*ELEMENT", 0) == 0;
      if (element_block) elset = line.substr(line.find("ELSET=") + 6);
      if (line.rfind("*FLUID SECTION", 0) == 0) {
        const std::size_t a = line.find("ELSET=") + 6, t = line.find("TYPE=") + 5;
        const std::string set = line.substr(a, line.find(',', a) - a), type = line.substr(t, line.find(',', t) - t);
        for (int id : sets[set]) d.type[id] = type;
      }
      continue;
    }
    if (element_block) {
      int id = 0, a = 0, m = 0, b = 0;
      char c = 0;
      std::istringstream ls(line);
      if (ls >> id >> c >> a >> c >> m >> c >> b) {
        d.elements[id] = {a, m, b};
        sets[elset].push_back(id);
      }
    }
  }
  return d;
}

/// ccx run on a copy of the deck: converged, and the .dat's pressures (MPa) and mass flows (t/s).
struct CcxRun {
  bool converged = false;
  std::string log;
  std::map<int, double> pressure, mass_flow;
};

inline CcxRun run_ccx(const std::filesystem::path& deck) {
  CcxRun r;
  TempDir dir("ccx");
  std::filesystem::copy_file(deck, dir.path / "net.inp");
  const std::string cmd = "cd '" + dir.path.string() + "' && timeout 60 ccx -i net > ccx.out 2>&1";
  const int rc = std::system(cmd.c_str());
  r.log = read_text(dir.path / "ccx.out");
  r.converged = rc == 0 && r.log.find("convergence in gas iteration") != std::string::npos;
  std::istringstream in(read_text(dir.path / "net.dat"));
  std::string line;
  std::map<int, double>* block = nullptr;
  while (std::getline(in, line)) {
    if (line.find("network pressures") != std::string::npos) block = &r.pressure;
    else if (line.find("mass flows") != std::string::npos) block = &r.mass_flow;
    else if (line.find("temperatures") != std::string::npos) block = nullptr;
    else if (block) {
      std::istringstream ls(line);
      int id = 0;
      double v = 0;
      if (ls >> id >> v) (*block)[id] = v;
    }
  }
  return r;
}

/// Mass balance of a ccx run at every corner node of the deck (node 0 is the outside): `worst` is the
/// largest imbalance over what is allowed there, 1e-6 of the node's throughput (half the sum of |flow|
/// of its elements: a hole with backflow brings coolant in through an element drawn as leaving) or, where
/// more, the rounding of the .dat's 7 significant digits (half a unit of the last digit of every flow).
struct NodeBalance {
  double worst = 0, worst_relative = 0;
  double supply = 0, exits = 0;  ///< t/s through the INOUT elements
};

inline NodeBalance node_balance(const DeckRead& deck, const CcxRun& run) {
  NodeBalance b;
  std::map<int, double> in, out, rounding, gross;
  for (const auto& [id, n] : deck.elements) {
    const double m = run.mass_flow.at(n[1]);
    const double half_digit = m == 0 ? 0 : 0.5 * std::pow(10.0, std::floor(std::log10(std::abs(m))) - 6);
    if (n[0] != 0) out[n[0]] += m, rounding[n[0]] += half_digit, gross[n[0]] += std::abs(m);
    if (n[2] != 0) in[n[2]] += m, rounding[n[2]] += half_digit, gross[n[2]] += std::abs(m);
    if (n[0] == 0) b.supply += m;
    if (n[2] == 0) b.exits += m;
  }
  for (const auto& [node, m_in] : in) {
    const double m_out = out[node], scale = 0.5 * gross[node];
    const double allowed = std::max(1e-6 * scale, rounding[node]);
    b.worst = std::max(b.worst, std::abs(m_in - m_out) / allowed);
    b.worst_relative = std::max(b.worst_relative, std::abs(m_in - m_out) / scale);
  }
  return b;
}

}  // namespace cg::test
