#pragma once
// film_holes.csv: every film and showerhead hole as the build placed it (FilmReport: exit point on the
// outer wall, axis, metering section), one line per hole, then every trailing-edge slot as the plan
// placed it (shape "slot": the centre of its opening under the lip for a cutback, the TE point where a
// centreline slot leaves the blade; inlet: the centre of its inlet face in the last chamber; axis inlet
// -> exit; diameter the hydraulic diameter 2 w h / (w + h); no inclination or compound angle), for CFD
// source models (TRACE film model, CFX injection regions, Fluent virtual holes; columns in
// docs/outputs.md). The solved mass flow of each hole and slot is filled in when a converged network
// solution is given, empty otherwise.
#include <string>

#include <vector>

#include "features/film/film_report.hpp"
#include "features/wall/trailing_edge.hpp"
#include "src/network/ccx_solve.hpp"
#include "src/network/network_model.hpp"

namespace cg::network {

std::string film_holes_csv(const features::FilmReport& film, const std::vector<features::SlotInfo>& slots, const Network* net,
                          const NetworkSolution* solution);

}  // namespace cg::network
