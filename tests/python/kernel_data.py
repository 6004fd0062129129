"""Geometry and parameters shared by tests/python/test_kernel.py and bench/bench_python_kernel.py, and
their text form for kernel_reference (every number as repr: the shortest text of the same double)."""
import numpy as np


def clamped_knots(degree, n_poles, rng, double_knot=False):
    """A clamped knot vector on [0, 1] with random interior knots (one of them doubled if asked)."""
    interior = np.sort(rng.uniform(0.05, 0.95, n_poles - degree - 1 - (1 if double_knot else 0)))
    if double_knot:
        interior = np.sort(np.append(interior, interior[len(interior) // 2]))
    return np.concatenate([np.zeros(degree + 1), interior, np.ones(degree + 1)])


def geometry(seed=23, n=10000):
    rng = np.random.default_rng(seed)
    g = {}
    g["c3"] = dict(degree=3, knots=clamped_knots(3, 12, rng, True), poles=rng.uniform(-50, 50, (12, 3)),
                   weights=rng.uniform(0.5, 2.0, 12))
    g["u"] = np.concatenate([[0.0, 1.0], rng.uniform(0, 1, n - 2)])
    g["p3"] = rng.uniform(-60, 60, (40, 3))
    # Two planar cubics that cross several times: a wave and a flatter, shifted wave.
    x = np.linspace(0, 100, 10)
    g["a"] = dict(degree=3, knots=clamped_knots(3, 10, rng), poles=np.stack([x, 20 * np.sin(x / 15)], axis=1),
                  weights=None)
    g["b"] = dict(degree=3, knots=clamped_knots(3, 10, rng), poles=np.stack([x, 8 * np.cos(x / 9) + 2], axis=1),
                  weights=rng.uniform(0.7, 1.4, 10))
    g["p2"] = rng.uniform(-10, 110, (40, 2))
    nu, nv = 6, 5
    grid = np.stack(np.meshgrid(np.linspace(0, 60, nu), np.linspace(0, 40, nv), indexing="ij"), axis=2)
    poles = np.concatenate([grid, rng.uniform(-8, 8, (nu, nv, 1))], axis=2)
    g["s"] = dict(degree_u=3, degree_v=2, knots_u=clamped_knots(3, nu, rng), knots_v=clamped_knots(2, nv, rng),
                  poles=poles, weights=rng.uniform(0.6, 1.6, (nu, nv)))
    g["us"], g["vs"] = rng.uniform(0, 1, 2000), rng.uniform(0, 1, 2000)
    g["ps"] = np.concatenate([rng.uniform(-10, 70, (30, 2)), rng.uniform(-20, 20, (30, 1))], axis=1)
    return g


def _list(values):
    values = np.asarray(values, dtype=float).ravel()
    return f"{len(values)} " + " ".join(repr(float(x)) for x in values) + "\n"


def _curve(c):
    return f"{c['degree']}\n" + _list(c["knots"]) + _list(c["poles"]) + _list([] if c["weights"] is None else c["weights"])


def write_values_input(g, path):
    s = g["s"]
    with open(path, "w") as f:
        f.write(_curve(g["c3"]) + _list(g["u"]) + _list(g["p3"]))
        f.write(_curve(g["a"]) + _curve(g["b"]) + _list(g["p2"]))
        f.write(f"{s['degree_u']} {s['degree_v']}\n" + _list(s["knots_u"]) + _list(s["knots_v"]))
        f.write(f"{s['poles'].shape[0]} {s['poles'].shape[1]}\n" + _list(s["poles"]) + _list(s["weights"]))
        f.write(_list(g["us"]) + _list(g["vs"]) + _list(g["ps"]))


def bench_curve(seed=5, n=10000):
    """The curve of bench/bench_evaluation.cpp's case (cubic, 50 poles, polynomial) and n sorted
    parameters (a tessellation's order)."""
    rng = np.random.default_rng(seed)
    c = dict(degree=3, knots=clamped_knots(3, 50, rng), poles=rng.uniform(-100, 100, (50, 3)), weights=None)
    return c, np.sort(rng.uniform(0, 1, n))


def write_time_input(c, u, path):
    with open(path, "w") as f:
        f.write(_curve(c) + _list(u))


def bench_surface(seed=7, n=10000):
    """A bicubic polynomial surface of 30 x 30 poles (bench/bench_evaluation.cpp's case) and n (u, v)
    pairs of a 100 x 100 grid, u outer (a tessellation's order)."""
    rng = np.random.default_rng(seed)
    grid = np.stack(np.meshgrid(np.linspace(0, 100, 30), np.linspace(0, 100, 30), indexing="ij"), axis=2)
    s = dict(degree_u=3, degree_v=3, knots_u=clamped_knots(3, 30, rng), knots_v=clamped_knots(3, 30, rng),
             poles=np.concatenate([grid, rng.uniform(-10, 10, (30, 30, 1))], axis=2), weights=None)
    side = int(round(np.sqrt(n)))
    u, v = np.meshgrid(np.linspace(0, 1, side), np.linspace(0, 1, side), indexing="ij")
    return s, u.ravel(), v.ravel()


def write_surface_time_input(s, u, v, path):
    with open(path, "w") as f:
        f.write(f"{s['degree_u']} {s['degree_v']}\n" + _list(s["knots_u"]) + _list(s["knots_v"]))
        f.write(f"{s['poles'].shape[0]} {s['poles'].shape[1]}\n" + _list(s["poles"]) + _list([]))
        f.write(_list(u) + _list(v))
