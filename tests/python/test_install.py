"""The installed package (issue 23): `cmake --install BUILD --prefix TMP --component python` puts coolinggen
in TMP/lib/python3/dist-packages, and a fresh interpreter with only that on PYTHONPATH (not the build tree)
imports it from there and runs the README's design loop (its ```python block in "## Python").

Usage: python3 test_install.py CMAKE BUILD_DIR README"""
import os
import re
import subprocess
import sys
import tempfile
from checks import check, finish

cmake, build_dir, readme = sys.argv[1:4]


with open(readme) as f:
    text = f.read()
section = text[text.index("\n## Python\n"):]
section = section[:section.index("\n## ", 1)]
loop = re.search(r"```python\n(.*?)```", section, re.S).group(1)

with tempfile.TemporaryDirectory() as prefix:
    r = subprocess.run([cmake, "--install", build_dir, "--prefix", prefix, "--component", "python"],
                       capture_output=True, text=True)
    check(r.returncode == 0, r.stdout + r.stderr)
    site = os.path.join(prefix, "lib", "python3", "dist-packages")
    files = sorted(os.listdir(os.path.join(site, "coolinggen")))
    check("__init__.py" in files and any(f.startswith("_coolinggen") and f.endswith(".so") for f in files),
          f"installed {files}")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = site
    where = subprocess.run([sys.executable, "-c", "import coolinggen; print(coolinggen.__file__)"],
                           capture_output=True, text=True, env=env, cwd=prefix)
    check(where.returncode == 0 and where.stdout.startswith(site), f"imported from {where.stdout!r} {where.stderr}")
    run = subprocess.run([sys.executable, "-c", loop], capture_output=True, text=True, env=env, cwd=prefix)
    check(run.returncode == 0, run.stderr)
    rows = [line.split() for line in run.stdout.splitlines()]
    print(run.stdout, end="")
    check(len(rows) == 2 and all(r[1] == "True" for r in rows), f"loop output {rows}")
    if len(rows) == 2:
        volumes = [float(r[2]) for r in rows]
        # Moving the 1 mm rib by 10 % of the chord changes the metal volume, by far less than 1 %.
        check(volumes[0] != volumes[1] and abs(volumes[0] - volumes[1]) < 0.01 * volumes[0], f"volumes {volumes}")
        check(all(float(r[3]) > 0 for r in rows), "clearances")
finish()
