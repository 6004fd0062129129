"""Per-point cost of coolinggen.BSplineCurve.evaluate and BSplineSurface.evaluate (Python, NumPy arrays)
against the C++ loops they wrap (CurveEvaluator<3>::points, SurfaceEvaluator<3>::points over the same
batch, timed by tests/python/kernel_reference in the same run), on batches of 10 000 points: sorted
parameters of a cubic 3D curve with 50 poles, a 100 x 100 grid on a bicubic 30 x 30 surface. Prints the
costs and their ratios; exits 1 when a ratio exceeds 1.5 (--quick, the CI smoke run on a shared
machine: 3).
The values themselves are compared with the C++ library's bit for bit by tests/python/test_kernel.py.

Usage: bench_python_kernel [--quick]   (the wrapper CMake writes into <build>/bench sets the paths)"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "python"))
sys.argv, quick = [a for a in sys.argv if a != "--quick"], "--quick" in sys.argv
import test_kernel  # noqa: E402  (reads the kernel_reference path from sys.argv[1])

reps, rounds, bound = (50, 2, 3.0) if quick else (2000, 7, 1.5)
worst = 0.0
for name, (py, cpp) in test_kernel.speed_ratios(reps, rounds).items():
    print(f"bench_python_kernel: {name} evaluate, 10 000 points per batch, best of {reps} x {rounds}: "
          f"Python {py:.3f} ns/point, C++ loop {cpp:.3f} ns/point, ratio {py / cpp:.3f} (bound {bound})")
    worst = max(worst, py / cpp)
sys.exit(0 if worst <= bound else 1)
