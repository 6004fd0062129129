"""coolinggen.build / validate / example / Result (issue 23): results equal the CLI's, errors are the CLI's
one-line messages as coolinggen exceptions, and no input, however wrong, ends the interpreter.

Usage: python3 test_build.py CLI   (CLI: the coolinggen executable of the same build)"""
import json
import math
import os
import pathlib
import random
import subprocess
import sys
import tempfile
import threading
import time

import numpy as np

import coolinggen
from light_configs import light_blade, two_chamber_blade
from checks import check, finish

CLI = sys.argv[1]


def cli(*args, cwd=None):
    r = subprocess.run([CLI, *args], capture_output=True, text=True, cwd=cwd)
    return r.returncode, r.stdout, r.stderr


def expect_config_error(config, field, part=""):
    """config raises ConfigError naming `field` (None: no field) with one line containing `part`."""
    try:
        coolinggen.validate(config)
    except coolinggen.ConfigError as e:
        msg = str(e)
        check(e.field == field, f"field {e.field!r} != {field!r}: {msg}")
        check("\n" not in msg and part in msg, f"expected one line with {part!r}: {msg!r}")
        check("json.exception" not in msg, f"JSON library id in {msg!r}")
        return msg
    except Exception as e:  # noqa: BLE001 - anything else is a failure of the test
        check(False, f"{field}: {type(e).__name__} instead of ConfigError: {e}")
        return None
    check(False, f"{field}: no error for {str(config)[:120]}")
    return None


def without_seconds(o):
    """o without its "seconds" entries (stage timings of the cooling report), recursively."""
    if isinstance(o, dict):
        return {k: without_seconds(v) for k, v in o.items() if k != "seconds"}
    if isinstance(o, list):
        return [without_seconds(v) for v in o]
    return o


def edited(edit):
    d = coolinggen.example()
    edit(d)
    return d


def test_example_and_version():
    with open(os.path.join(os.path.dirname(__file__), "../../data/examples/hpt_rotor.json")) as f:
        check(coolinggen.example() == json.load(f), "example() is data/examples/hpt_rotor.json")
    code, out, _ = cli("--version")
    check(code == 0 and out.strip() == "coolinggen " + coolinggen.__version__, f"version {out!r}")
    check(coolinggen.validate(coolinggen.example()) == {"name": "hpt_rotor", "flow_path": "meridional", "sections": 3, "notes": []},
          "validate(example)")


# The hostile configs of tests/cli/test_config.cpp (missing fields, out of range, unknown keys, wrong
# types, integers) and what only Python can pass (NaN, inf, sets, non-str keys, objects, deep nesting).
def set_(path, value):
    def edit(d):
        o = d
        for k in path[:-1]:
            o = o[k]
        o[path[-1]] = value
    return edit


def drop(path):
    def edit(d):
        o = d
        for k in path[:-1]:
            o = o[k]
        del o[path[-1]]
    return edit


HOSTILE = [
    (drop(["units"]), "units", "missing"),
    (drop(["sections"]), "sections", "missing"),
    (drop(["sections", 1, "parametric", "chord"]), "sections[1].parametric.chord", "missing"),
    (drop(["flow_path", "casing"]), "flow_path.casing", "missing"),
    (set_(["sections"], []), "sections", "at least 1"),
    (set_(["sections", 2, "parametric", "max_thickness"], -1.0), "sections[2].parametric.max_thickness", ""),
    (set_(["sections", 0, "parametric", "chord"], 0.0), "sections[0].parametric.chord", "(0, 100000] mm"),
    (set_(["sections", 1, "span"], 1.5), "sections[1].span", "[0, 1]"),
    (set_(["flow_path", "hub", 1, 1], -5.0), "flow_path.hub[1][1]", "> 0 mm"),
    (set_(["blade", "overbuild"], 0.0), "blade.overbuild", "(0, 0.5]"),
    (set_(["units"], "cm"), "units", '"mm"'),
    (set_(["cooling"], {}), "cooling", "no cooling feature given"),
    (set_(["colour"], "red"), "colour", "unknown key"),
    (set_(["blade", "degree"], 3), "blade.degree", "allowed here: overbuild"),
    (set_(["flow_path", "hub"], "abc"), "flow_path.hub", "must be an array, got string"),
    (set_(["sections", 0, "parametric", "chord"], "30"), "sections[0].parametric.chord", ""),
    (set_(["sections"], {}), "sections", "must be an array, got object"),
    (set_(["sections", 0, "offset"], [1, True]), "sections[0].offset[1]", "must be a number"),
    (set_(["blade", "chordwise_samples"], 97.5), "blade.chordwise_samples", "must be an integer, got number 97.5"),
    (set_(["blade", "chordwise_samples"], 1e30), "blade.chordwise_samples", "[8, 2000]"),
    (set_(["blade", "chordwise_samples"], 3000000000), "blade.chordwise_samples", "[8, 2000]"),
    (set_(["blade", "chordwise_samples"], 10 ** 30), "blade.chordwise_samples", "[8, 2000]"),
    (set_(["blade", "chordwise_samples"], 10 ** 400), "blade.chordwise_samples", "integer out of the range"),
    (set_(["blade", "chordwise_samples"], -(10 ** 30)), "blade.chordwise_samples", "[8, 2000]"),
    (set_(["cooling", "film_rows", 0, "count"], 10 ** 9), "cooling.film_rows[0].count", ""),
    (set_(["sections", 0, "parametric", "chord"], float("nan")), "sections[0].parametric.chord", "finite number, got nan"),
    (set_(["sections", 0, "parametric", "chord"], float("inf")), "sections[0].parametric.chord", "got inf"),
    (set_(["sections", 0, "parametric", "chord"], np.float64("nan")), "sections[0].parametric.chord", "got nan"),
    (set_(["sections", 0, "parametric", "chord"], np.float32(-1)), "sections[0].parametric.chord", ""),
    (set_(["flow_path", "hub"], np.array([[0, 1.0], [1.0, float("nan")]])), "flow_path.hub[1][1]", "got nan"),
    (set_(["sections", 0, "parametric", "chord"], {1, 2}), "sections[0].parametric.chord", "got set"),
    (set_(["sections", 0, "parametric", "chord"], object()), "sections[0].parametric.chord", "got object"),
    (set_(["sections", 0, "parametric", "chord"], b"30"), "sections[0].parametric.chord", "got bytes"),
    (set_(["sections", 0, "parametric", "chord"], 3 + 4j), "sections[0].parametric.chord", "got complex"),
    (set_(["blade", 7], 1), "blade", "keys must be strings"),
    (set_(["name"], "\ud800"), "name", "not valid Unicode"),
    (set_(["name"], 12), "name", ""),
]


def test_hostile_configs():
    for edit, field, part in HOSTILE:
        expect_config_error(edited(edit), field, part)
    deep = []
    for _ in range(100000):  # deeper than any C++ recursion could take
        deep = [deep]
    expect_config_error(edited(set_(["description"], deep)), "description" + "[0]" * 100, "nested deeper than 100")
    for value, part in [(3, "got int"), (None, "got NoneType"), ([1, 2], "got list"), (b"{}", "got bytes"),
                        ("", "empty path"), (1.5, "got float")]:
        expect_config_error(value, "config", part)
    for text, part in [("{\"units\": \"mm\",\n \"flow_path\": }", "config line 2, column 15: syntax error"),
                       ("{\"units\": \"mm\", \"units\": \"mm\"}", "units: duplicate key"),
                       ("{\"x\": -1e400}", "out of range")]:
        expect_config_error(text, None if "line" in part or "range" in part else "units", part)
    expect_config_error("/nonexistent/blade.json", "config", "does not exist")
    expect_config_error(pathlib.Path(tempfile.gettempdir()), "config", "is a directory")
    # outputs and timeout are checked before the build.
    for outputs, part in [(["step", "igs"], 'output.formats[1]: unknown output format "igs"'), ("stp", "unknown"),
                          ([3], "got an item of type int"), (3, "got int")]:
        try:
            coolinggen.build(light_blade(), outputs=outputs)
            check(False, f"outputs {outputs!r} accepted")
        except coolinggen.ConfigError as e:
            check(part in str(e), f"outputs {outputs!r}: {e}")
    for timeout in [0, -1, float("nan"), "10", True]:
        try:
            coolinggen.build(light_blade(), timeout=timeout)
            check(False, f"timeout {timeout!r} accepted")
        except coolinggen.ConfigError as e:
            check(str(e).startswith("timeout: must be None or a number of seconds > 0"), f"timeout {timeout!r}: {e}")
    try:
        coolinggen.build(light_blade(), progress=3)
        check(False, "progress=3 accepted")
    except TypeError as e:
        check("progress must be None or a callable" in str(e), str(e))


def test_messages_equal_the_cli():
    """The same bad config as a file: `coolinggen validate` prints exactly 'coolinggen: error: ' + str(e)."""
    with tempfile.TemporaryDirectory() as tmp:
        for i, (edit, _field, _part) in enumerate(HOSTILE[:22]):
            d = edited(edit)
            path = os.path.join(tmp, f"bad{i}.json")
            with open(path, "w") as f:
                json.dump(d, f)
            code, _, err = cli("validate", path)
            try:
                coolinggen.validate(path)
                check(False, f"{path}: no error")
            except coolinggen.ConfigError as e:
                check(code == 2 and err == f"coolinggen: error: {e}\n", f"CLI {code} {err!r} vs {e}")
                try:
                    coolinggen.validate(d)
                    check(False, "dict: no error")
                except coolinggen.ConfigError as e2:
                    check(str(e2) == str(e), f"dict {e2} vs file {e}")


def test_random_hostile_values():
    """Random leaves of the example replaced by hostile values: validate raises ConfigError or succeeds."""
    rng = random.Random(23)
    hostile = [float("nan"), -float("inf"), 1e308, -1e-308, 0, -1, 10 ** 20, "x", "", None, True, [], {}, [[1e9]],
               {"a": 1}, 2 ** 31, -0.0]
    base = coolinggen.example()

    def leaves(o, path):
        if isinstance(o, dict):
            for k, v in o.items():
                yield from leaves(v, path + [k])
        elif isinstance(o, list):
            for i, v in enumerate(o):
                yield from leaves(v, path + [i])
        yield path

    paths = [p for p in leaves(base, []) if p]
    raised = 0
    for _ in range(300):
        d = json.loads(json.dumps(base))
        for _ in range(rng.randint(1, 3)):
            p = rng.choice(paths)
            try:
                set_(p, rng.choice(hostile))(d)
            except (KeyError, IndexError, TypeError):  # the path went away with an earlier edit
                pass
        try:
            coolinggen.validate(d)
        except coolinggen.ConfigError as e:
            raised += 1
            check("\n" not in str(e), f"multi-line message {e!r}")
        except Exception as e:  # noqa: BLE001
            check(False, f"{type(e).__name__}: {e}")
    check(raised > 200, f"only {raised} of 300 hostile variants raised")
    print(f"random hostile variants: {raised} of 300 raised ConfigError, none crashed")


def test_build_equals_cli():
    with tempfile.TemporaryDirectory() as tmp:
        d = two_chamber_blade()
        d["output"]["formats"] = ["step"]
        path = os.path.join(tmp, "two_chamber.json")
        with open(path, "w") as f:
            json.dump(d, f)
        code, _, err = cli("build", path, "-q", "-o", os.path.join(tmp, "cli"))
        check(code == 0, err)
        with open(os.path.join(tmp, "cli", "report.json")) as f:
            ref = json.load(f)
        r = coolinggen.build(path)
        check(r.valid and r.failed_checks == [], f"valid {r.valid} {r.failed_checks}")
        written = r.write(os.path.join(tmp, "py"))
        check(written == ["blade.step", "report.json"], f"written {written}")
        check(sorted(os.listdir(os.path.join(tmp, "py"))) == sorted(os.listdir(os.path.join(tmp, "cli"))), "same files")
        for key in ["input_hash", "valid", "solid", "checks", "bodies", "outputs"]:
            check(r.report[key] == ref[key], f"report[{key!r}] differs from the CLI's")
        check(without_seconds(r.report["model"]) == without_seconds(ref["model"]), "model section differs")
        # A config as a dict and as a file: the same model and input hash (model.source differs).
        light = light_blade()
        light_path = os.path.join(tmp, "light.json")
        with open(light_path, "w") as f:
            json.dump(light, f)
        r1, r2 = coolinggen.build(light_path, outputs="none"), coolinggen.build(light, outputs="none")
        for key in ["input_hash", "valid", "solid", "checks", "bodies"]:
            check(r2.report[key] == r1.report[key], f"dict and file: report[{key!r}] differs")
        check(r2.report["model"]["source"] == "<python dict>" and r2.report["outputs"] == [], "dict report")
        # write() over a directory of another run: the earlier run's files go, the user's stay.
        out = os.path.join(tmp, "py")
        with open(os.path.join(out, "mine.txt"), "w") as f:
            f.write("a file of the user")
        check(r2.write(out) == ["report.json"], "report only")
        check(sorted(os.listdir(out)) == ["mine.txt", "report.json"], f"after rewrite: {os.listdir(out)}")
        check(r2.report["outputs"] == ["report.json"], "written report")
        try:
            r2.write(os.path.join(out, "mine.txt"))
            check(False, "write into a file")
        except coolinggen.OutputError as e:
            check("exists and is not a directory" in str(e) and isinstance(e, OSError), str(e))


def test_impossible_core():
    d = light_blade()
    d["sections"][0]["parametric"]["max_thickness"] = 12.0
    d["cooling"] = {"core": {"wall_thickness": 5.9, "tip_cap": {"thickness": 1.0}, "hub_floor": {"thickness": 1.0},
                             "inlets": [{"chamber": 1, "end": "hub", "diameter": 1.0}]}}
    try:
        coolinggen.build(d, outputs="none")
        check(False, "a 5.9 mm wall in a 12 mm blade built")
    except coolinggen.Error as e:  # ConfigError (fail-fast check) or FeatureFailure, never a crash
        check(type(e) in (coolinggen.ConfigError, coolinggen.FeatureFailure), f"{type(e).__name__}: {e}")
        print(f"5.9 mm wall: {type(e).__name__}: {e}")


def test_progress_gil_and_cancel():
    events = []
    r = coolinggen.build(light_blade(), outputs="none", progress=lambda *a: events.append(a))
    stages = [s for s, f, _ in events if f == 0.0]
    check(stages == ["blade_model", "solid", "verify"], f"stages {stages}")
    check(all(0.0 <= f <= 1.0 for _, f, _ in events), "fractions in [0, 1]")
    check(list(r.report["timings_s"]) == stages, f"timings {list(r.report['timings_s'])}")
    # The GIL is released: a pure-Python thread runs while the build does.
    count, done = [0], [False]

    def spin():
        while not done[0]:
            count[0] += 1

    t = threading.Thread(target=spin)
    t.start()
    before = count[0]
    coolinggen.build(light_blade(), outputs="none")
    during = count[0] - before
    done[0] = True
    t.join()
    check(during > 10000, f"the Python thread counted {during} during the build")
    print(f"Python thread iterations during a build: {during}")
    # Builds from two Python threads at once (they run one after the other inside): both valid.
    results = [None, None]

    def build_into(k):
        results[k] = coolinggen.build(light_blade(f"thread{k}", 10.0 + k), outputs="none")

    threads = [threading.Thread(target=build_into, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    check(all(r is not None and r.valid for r in results), f"threaded builds {results}")
    check(results[0].report["solid"]["volume_mm3"] < results[1].report["solid"]["volume_mm3"], "10 mm < 11 mm span")
    # A callback that raises stops the build with its exception.
    try:
        coolinggen.build(light_blade(), progress=lambda *a: 1 / 0)
        check(False, "raising callback")
    except ZeroDivisionError:
        pass
    # Timeout: Cancelled with the CLI's reason.
    try:
        coolinggen.build(two_chamber_blade(), timeout=1e-6)
        check(False, "timeout")
    except coolinggen.Cancelled as e:
        check(str(e).startswith("time limit of 1e-06 s reached: stopped ") and str(e).endswith("; nothing built"), str(e))
    # Ctrl-C (SIGINT to this process) while the build runs: Cancelled naming the stage; no KeyboardInterrupt.
    import signal

    sent = [False]

    def interrupt(stage, fraction, step):
        if not sent[0]:
            sent[0] = True
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(0.3)  # the waiting thread sees the signal meanwhile

    try:
        coolinggen.build(two_chamber_blade(), progress=interrupt)
        check(False, "Ctrl-C did not stop the build")
    except coolinggen.Cancelled as e:
        check(str(e).startswith("interrupted (Ctrl-C): stopped "), str(e))
        print("Ctrl-C:", e)


for test in [test_example_and_version, test_hostile_configs, test_messages_equal_the_cli, test_random_hostile_values,
             test_build_equals_cli, test_impossible_core, test_progress_gil_and_cancel]:
    t0 = time.time()
    test()
    print(f"{test.__name__}: {time.time() - t0:.2f} s")
finish()
