"""Light variants of the built-in example for the Python tests (build in well under a second)."""
import coolinggen


def light_blade(name="light", span=20.0):
    """The example's mid-span section as a short straight uncooled blade (as tests/support/short_blade.hpp,
    without cooling)."""
    d = coolinggen.example()
    d["name"] = name
    d["flow_path"] = {"type": "straight", "span": span}
    mid = d["sections"][1]
    mid["span"] = 0.0
    mid["parametric"]["max_thickness"] = 12.0
    mid["parametric"]["le_radius"] = 2.6
    d["sections"] = [mid]
    d.pop("cooling")
    return d


def two_chamber_blade(name="two_chamber", span=12.0):
    """The cooled light blade of tests/mesh/test_mesh_cgns.cpp: light_blade with the two-chamber core of
    tests/support/short_blade.hpp (one filleted rib) and a row of two film holes."""
    d = light_blade(name, span)
    d["cooling"] = {"film_rows": [{"diameter": 0.4, "chord": -0.45, "count": 2, "inclination_deg": 35,
                                   "span_start": 0.35, "span_end": 0.65, "chamber": 2}],
                    "core": {
        "wall_thickness": 1.0, "tip_cap": {"thickness": 1.0}, "hub_floor": {"thickness": 1.0},
        "ribs": [{"suction_chord": 0.3, "pressure_chord": -0.3, "thickness": 1.0, "fillet_radius": 0.3}],
        "inlets": [{"chamber": 1, "end": "hub", "diameter": 1.0}, {"chamber": 2, "end": "hub", "diameter": 1.2}]}}
    return d
