#pragma once
// film_holes.csv: every film and showerhead hole as the build placed it (FilmReport: exit point on the
// outer wall, axis, metering section), one line per hole, for CFD source models (TRACE film model, CFX
// injection regions, Fluent virtual holes; columns in docs/outputs.md). The solved mass flow of each
// hole is filled in when a converged network solution is given, empty otherwise.
#include <string>

#include "features/film/film_report.hpp"
#include "src/network/ccx_solve.hpp"
#include "src/network/network_model.hpp"

namespace cg::network {

std::string film_holes_csv(const features::FilmReport& film, const Network* net, const NetworkSolution* solution);

}  // namespace cg::network
