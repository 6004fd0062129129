#pragma once
// The coolant circuit of a built blade as a flow network (network_model.hpp, docs/network.md), from the
// part as built: chamber and passage sections measured on the built cavity (the passage report's
// sections, span_sections.hpp), every film and showerhead hole as placed and measured by the film stage
// (FilmReport), trailing-edge slots and wall features counted by their faces on the blade.
//
//   supply -> inlet orifice -> chamber stations (>= 10 measured sections, end pieces to the end walls)
//          -> bend (turnaround) -> next chamber ... ; every hole / slot from the station nearest its inlet
//          to the sink of its kind; rotors: a forced vortex in series with each segment.
#include <stdexcept>

#include "features/film/film_report.hpp"
#include "features/passages/passage_report.hpp"
#include "features/wall/trailing_edge.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/brep/named_shape.hpp"
#include "src/config/config.hpp"
#include "src/network/network_model.hpp"

namespace cg::network {

/// The circuit cannot be made from this part (e.g. a chamber without measured sections).
class NetworkError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct NetworkInput {
  const config::Config* config = nullptr;  ///< cooling definitions and "coolant" (required)
  const blade::BladeModel* model = nullptr;
  const brep::Part* part = nullptr;
  const features::PassageReport* passages = nullptr;  ///< required
  const features::FilmReport* film = nullptr;         ///< optional
  /// The trailing-edge slots as placed (optional): their rows of film_holes.csv.
  const std::vector<features::SlotInfo>* slots = nullptr;
};

/// Builds the network. Throws NetworkError when the part has no measured passage.
Network build_network(const NetworkInput& in);

}  // namespace cg::network
