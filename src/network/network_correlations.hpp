#pragma once
// The published correlations the network applies where CalculiX has no element of its own (sources and
// validity ranges in docs/network.md): gas properties of air, rib-turbulated channel friction (Han),
// pin-fin bank loss (Metzger et al.).
#include "features/passages/passage_definition.hpp"
#include "src/network/network_model.hpp"

namespace cg::network {

/// Air: cp (J/(kg K)), ideal-gas polynomial, 273-1800 K (clamped outside).
double air_cp(double t);
/// Air: dynamic viscosity (Pa s), Sutherland's law (mu_0 1.716e-5 Pa s at 273.15 K, S = 110.4 K).
double air_viscosity(double t);

/// Rib turbulators on a segment of hydraulic diameter `dh` and aspect ratio `aspect` (W / H of the
/// equivalent rectangle, ribs on the W walls): e/Dh, P/e, angle, and the fully rough Fanning friction
/// factor of the ribbed walls from Han's rib-roughness function R(e+) (docs/network.md).
Turbulation turbulation(const features::TurbulatorDefinition& t, double dh, double aspect, double length);
/// The sand roughness k_s (mm) that gives a fully rough Colebrook pipe of diameter `dh` the segment's
/// perimeter-weighted friction factor (ribbed walls f_r, smooth walls a smooth channel's at Re 2e4).
double equivalent_roughness(const Turbulation& t, double dh);
/// A staggered pin-fin bank: S/D, X/D, rows, and the loss per row in velocity heads at the minimum gap
/// at Re_D = 1e4 (pin_row_loss; the network stage moves it to the solved flow's Re_D).
PinBank pin_bank(const features::PinFinDefinition& p, int pins);
/// Loss per pin row in velocity heads at the minimum gap: K = 4 f with Metzger's staggered short-pin
/// friction factor f = 0.317 Re_D^-0.132 (Re_D on the pin diameter and the gap velocity; clamped to the
/// correlation's range 1e3-1e5).
double pin_row_loss(double re_d);

}  // namespace cg::network
