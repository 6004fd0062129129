#!/usr/bin/env python3
"""Random designs through `coolinggen build`: does every design build or get refused clearly?

Seeded, plausible variants of the built-in example (data/examples/hpt_rotor.json) and of the C3X film vane
(data/examples/c3x_film_vane.json), covering every cooling feature and its options: blade stagger and
thickness, wall thickness, 1-4 ribs with and without fillets and turnarounds, inlets, turbulators, the TE
cutback with 0-3 pin rows, 0-4 film rows (cylindrical and 7-7-7), the showerhead on or off, the C3X insert,
the C3X inlets through the hub floor or the tip cap (drawn from a stream of their own, so the other draws
of a seed are those of the runs before it).
Half the variants are drawn "inside" (positions and sizes inside the ranges the error messages state: film
rows fed from the chamber they sit over, turbulators between two ribs, ...), half "free" (wider ranges,
no such care).

Film rows are drawn without `chamber` too (NO_CHAMBER of them, inside and free), as a user who does not
care writes them. Each variant goes through `coolinggen validate`, then `coolinggen build` (both run, so
that every refusal of validate is compared with build's), each by the coolinggen binary as a separate
process (a crash cannot take the bench down), --jobs at a time with `--threads` CPUs / jobs each (as
`coolinggen sweep` shares the CPUs among its variants), the build with `--timeout`; the build is classified:
  built    exit 0, report.json says valid, every body valid;
  refused  exit 2 with a one-line error that names a config field (`cooling.core.ribs[1].thickness: ...`);
  failed   anything else (exit 3: a boolean or check CoolingGen could not complete, said as such; exit
           4/5, a signal, a timeout, a multi-line or field-less refusal, an invalid report): a bug to fix.
Printed: the counts (overall and for the "inside" half: goal 0 failed, >= 90 % of "inside" built), the
refusal reasons grouped by field, the failures with their messages, and the time to refusal against the
median build time (goal: a refusal within 5 % of a build; a refusal's time is validate's when validate
refused it, else build's), and validate against build: a refused variant agrees when validate refused it
naming the same field; "late refusals" are those validate accepted (checks that need the built cavity).
Exit 1 when any variant failed, or when fewer than --min-built of the variants built (a bench whose
variants are all refused shows nothing).

Usage: random_designs.py --binary build/coolinggen [--count 200] [--seed 1] [--jobs 2] [--light]
                         [--timeout 900] [--keep DIR] [--min-built 0.5]
--light: film rows and showerhead over 5 % of the span, coarser turbulator/slot/pin pitches (a build
takes a few seconds; CI runs --count 6 --light --seed 3).
"""
import argparse
import concurrent.futures
import copy
import json
import os
import random
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLES = os.path.join(ROOT, "data", "examples")


def load(name):
    """An example config with its point files made absolute (the variants are written elsewhere)."""
    with open(os.path.join(EXAMPLES, name)) as f:
        doc = json.load(f)
    for s in doc["sections"]:
        points = s.get("points", {})
        if "file" in points and not os.path.isabs(points["file"]):
            points["file"] = os.path.normpath(os.path.join(EXAMPLES, points["file"]))
    return doc


# Film rows drawn without "chamber" (the row is fed from the chamber its holes enter), inside and free.
NO_CHAMBER = 0.4


def chamber_at(chord, ribs):
    """The chamber (1-based, LE chamber = 1) a film row at `chord` sits over: suction side chord > 0
    against the ribs' suction_chord, pressure side chord < 0 against pressure_chord."""
    key = "suction_chord" if chord > 0 else "pressure_chord"
    return 1 + sum(1 for r in ribs if abs(r[key]) < abs(chord))


def draw_ribs(rng, inside, count, span_mm):
    """`count` ribs spread over the chord (suction/pressure positions), thickness, fillets, turnarounds."""
    lo, hi = (0.2, 0.72) if inside else (0.08, 0.9)
    pos = sorted(rng.uniform(lo, hi) for _ in range(count))
    if inside:  # (hi - lo) / count of the chord between ribs +-0.06 on the suction side (0.07 apart at 4 ribs;
        # the pressure chords lie 0.05 below to 0.03 above: 0.04 apart seen) for a chamber and its fillets
        pos = [lo + (hi - lo) * (k + 0.5) / count + rng.uniform(-0.03, 0.03) for k in range(count)]
    ribs = []
    serpentine = rng.random() < 0.6
    for k, s in enumerate(pos):
        rib = {"suction_chord": round(s, 4), "pressure_chord": round(-(s + rng.uniform(-0.05, 0.03)), 4),
               "thickness": round(rng.uniform(0.8, 1.4) if inside else rng.uniform(0.4, 2.2), 4)}
        if rng.random() < 0.7:
            limit = 0.5 * rib["thickness"]
            rib["fillet_radius"] = round(rng.uniform(0.2, min(0.6, limit)) if inside else rng.uniform(0.1, 1.5), 4)
        if serpentine and k >= 1:
            end = "tip" if k % 2 == 1 else "hub"
            gap = rng.uniform(2.0, 3.0) if inside else rng.uniform(0.5, 0.3 * span_mm)
            ta = {"end": end, "gap": round(gap, 4)}
            if rng.random() < 0.5:
                ta["tip_radius"] = round(0.5 * rib["thickness"] * (rng.uniform(0.3, 0.9) if inside else rng.uniform(0.2, 1.6)), 4)
            rib["turnaround"] = ta
        ribs.append(rib)
    return ribs


def inlets_for(ribs, rng, inside):
    """One hub inlet per group of chambers joined by turnarounds (every chamber must be fed)."""
    chambers = len(ribs) + 1
    inlets, k = [], 1
    while k <= chambers:
        inlets.append({"chamber": k, "end": "hub", "diameter": round(rng.uniform(1.0, 1.6) if inside else rng.uniform(0.5, 5.0), 4)})
        k += 1
        while k <= chambers and "turnaround" in ribs[k - 2]:  # rib k-1 between chamber k-1 and k
            k += 1
    return inlets


def vary_rotor(rng, inside, light):
    d = load("hpt_rotor.json")
    stagger = rng.uniform(-8, 8) if inside else rng.uniform(-15, 15)
    thick = rng.uniform(0.9, 1.15) if inside else rng.uniform(0.7, 1.4)
    for s in d["sections"]:
        p = s["parametric"]
        p["stagger_deg"] = round(p["stagger_deg"] + stagger, 4)
        p["max_thickness"] = round(p["max_thickness"] * thick, 4)
    c = d["cooling"]
    core = c["core"]
    core["wall_thickness"] = round(rng.uniform(0.7, 1.2) if inside else rng.uniform(0.4, 2.0), 4)
    ribs = draw_ribs(rng, inside, rng.randint(1, 4), 50.0)
    core["ribs"] = ribs
    core["inlets"] = inlets_for(ribs, rng, inside)
    chambers = len(ribs) + 1
    turb = []
    if chambers >= 3 and rng.random() < 0.6:
        for ch in rng.sample(range(2, chambers), k=min(chambers - 2, rng.randint(1, 2))):
            turb.append({"chamber": ch, "walls": rng.choice(["pressure", "suction", "both"]),
                         "height": round(rng.uniform(0.3, 0.5) if inside else rng.uniform(0.1, 1.2), 4),
                         "width": round(rng.uniform(0.4, 0.7), 4),
                         "pitch": round((12.0 if light else rng.uniform(4.0, 7.0)), 4),
                         "angle_deg": round(rng.choice([90, 60, 45]) if inside else rng.uniform(20, 90), 4)})
    if turb:
        core["turbulators"] = turb
    else:
        core.pop("turbulators", None)
    if rng.random() < 0.7:
        te = core["trailing_edge"]
        te["pitch"] = 10.0 if light else round(rng.uniform(2.2, 3.5), 4)
        te["cutback_length"] = round(rng.uniform(0.3, 0.6) if inside else rng.uniform(0.1, 4.0), 4)
        rows = rng.randint(0, 3 if inside else 5)
        if rows:
            te["pin_fins"] = {"diameter": round(rng.uniform(0.6, 0.9), 4),
                              "spanwise_pitch": 10.0 if light else round(rng.uniform(2.2, 3.0), 4),
                              "streamwise_pitch": round(rng.uniform(1.4, 1.8) if inside else rng.uniform(0.8, 3.0), 4), "rows": rows}
        else:
            te.pop("pin_fins", None)
    else:
        core.pop("trailing_edge", None)
    span = (0.5, 0.55) if light else (0.1, 0.9)
    rows = []
    for _ in range(rng.randint(0, 4)):
        side = rng.choice([-1, 1])
        chord = side * (rng.uniform(0.12, 0.85) if inside else rng.uniform(0.02, 0.98))
        if inside:  # a row's bores run ~3 mm along the wall to the cavity: keep them 0.1 chord off the ribs
            key = "suction_chord" if chord > 0 else "pressure_chord"
            if any(abs(abs(chord) - abs(r[key])) < 0.1 for r in ribs):
                continue
        ch = chamber_at(chord, ribs) if inside else rng.randint(1, chambers + 1)
        row = {"diameter": round(rng.uniform(0.3, 0.5), 4), "chord": round(chord, 4),
               "inclination_deg": round(rng.uniform(25, 40) if inside else rng.uniform(5, 80), 4),
               "span_start": span[0], "span_end": span[1], "chamber": ch}
        if rng.random() < NO_CHAMBER:  # as a user who does not care writes it: fed from where it enters
            del row["chamber"]
        if rng.random() < 0.3:
            row["shape"] = "7-7-7"
        else:
            row["pitch_d"] = round(rng.uniform(4, 7) if inside else rng.uniform(1.2, 10), 4)
        rows.append(row)
    if inside:  # keep rows apart along the chord (a ligament between rows)
        rows.sort(key=lambda r: r["chord"])
        rows = [r for i, r in enumerate(rows) if i == 0 or abs(r["chord"] - rows[i - 1]["chord"]) > 0.08]
    if rows:
        c["film_rows"] = rows
    else:
        c.pop("film_rows", None)
    if rng.random() < 0.6:
        sh = c["showerhead"]
        sh["span_start"], sh["span_end"] = span
        sh["rows"] = rng.randint(1, 3) if light else rng.randint(1, 5)
    else:
        c.pop("showerhead", None)
    return d


def vary_c3x(rng, inside, light):
    d = load("c3x_film_vane.json")
    c = d["cooling"]
    core = c["core"]
    core["wall_thickness"] = round(rng.uniform(1.8, 3.0) if inside else rng.uniform(0.8, 4.0), 4)
    rib = core["ribs"][0]
    s = rng.uniform(0.25, 0.4) if inside else rng.uniform(0.1, 0.7)
    rib["suction_chord"], rib["pressure_chord"] = round(s, 4), round(-s, 4)
    rib["thickness"] = round(rng.uniform(2.5, 3.5) if inside else rng.uniform(1.0, 5.0), 4)
    span = (0.5, 0.55) if light else (0.1, 0.9)
    for r in c.get("film_rows", []):
        r["span_start"], r["span_end"] = span
        r["pitch_d"] = round(rng.uniform(3.5, 6) if inside else rng.uniform(1.1, 10), 4)
        r["chord"] = round((1 if r["chord"] > 0 else -1) * (rng.uniform(s + 0.1, 0.6) if inside else rng.uniform(0.05, 0.95)), 4)
        if rng.random() < NO_CHAMBER:
            del r["chamber"]
    sh = c["showerhead"]
    sh["span_start"], sh["span_end"] = span
    sh["rows"] = rng.randint(1, 3) if light else rng.randint(1, 5)
    if rng.random() < 0.3:
        c.pop("inserts", None)
    else:
        ins = c["inserts"][0]
        ins["gap"] = round(rng.uniform(1.3, 2.0) if inside else rng.uniform(0.2, 4.0), 4)
        ins["sheet_thickness"] = round(rng.uniform(0.4, 0.8), 4)
        if light:
            ins["jets"]["spacing_x_d"] = ins["jets"]["spacing_y_d"] = 20
    return d


def feed_ends(doc, rng):
    """Each inlet through the hub floor or the tip cap, one in two."""
    for inlet in doc["cooling"]["core"]["inlets"]:
        inlet["end"] = rng.choice(["hub", "tip"])


FIELD = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*(\[\d+\])?)(\.[A-Za-z_][A-Za-z0-9_]*(\[\d+\])?)*: ")


def classify(exit_code, err, report):
    lines = [l for l in err.strip().splitlines() if l.strip()]
    if exit_code == 0:
        ok = report is not None and report.get("valid") is True and all(b.get("valid") for b in report.get("bodies", []))
        return ("built", "", "") if ok else ("failed", "exit 0 but the report says invalid", "")
    if exit_code == 3:
        return "failed", "CoolingGen failure (exit 3): " + " | ".join(lines)[:300], ""
    if exit_code == 2:
        if len(lines) == 1:
            m = FIELD.match(lines[0].removeprefix("coolinggen: error: "))
            if m:
                return "refused", m.group(0)[:-2], lines[0]
        return "failed", "refusal without a one-line field error: " + " | ".join(lines)[:300], ""
    return "failed", "exit %d: %s" % (exit_code, " | ".join(lines)[:300]), ""


def field_group(field):
    """cooling.core.ribs[2].thickness -> cooling.core.ribs[].thickness (refusal reasons by field)."""
    return re.sub(r"\[\d+\]", "[]", field)


def run_command(binary, args, timeout):
    """(exit code, stderr, seconds) of one coolinggen command in its own process."""
    t0 = time.monotonic()
    try:
        p = subprocess.run([binary] + args, capture_output=True, text=True, timeout=timeout)
        code, err = p.returncode, p.stderr
    except subprocess.TimeoutExpired:
        code, err = -999, "killed: no exit within %g s" % timeout
    return code, err, time.monotonic() - t0


def run_variant(binary, work, index, doc, timeout, threads):
    """`coolinggen validate`, then `coolinggen build` of one variant (build runs either way: a design
    validate refuses must be refused by build naming the same field), each on `threads` threads (a
    study's share of the CPUs per variant, as `coolinggen sweep --jobs` gives it)."""
    cfg = os.path.join(work, "v%03d.json" % index)
    out = os.path.join(work, "v%03d" % index)
    doc.setdefault("output", {})["formats"] = []  # report.json alone: the build and its checks are the test
    with open(cfg, "w") as f:
        json.dump(doc, f, indent=1)
    vcode, verr, vseconds = run_command(binary, ["validate", cfg, "--threads", str(threads)], 120)
    vstatus, vdetail, _ = classify(vcode, verr, None) if vcode != 0 else ("valid", "", "")
    code, err, seconds = run_command(binary, ["build", cfg, "-q", "-o", out, "--timeout", str(timeout), "--threads", str(threads)], timeout + 120)
    report = None
    try:
        with open(os.path.join(out, "report.json")) as f:
            report = json.load(f)
    except (OSError, ValueError):
        pass
    status, detail, message = classify(code, err, report)
    return {"index": index, "status": status, "detail": detail, "message": message, "seconds": seconds, "exit": code,
            "validate": vstatus, "validate_detail": vdetail, "validate_seconds": vseconds}


def agreement(r):
    """How `validate` and `build` agree on a variant: "agree", "late" (validate said valid, build refused:
    a check that needs the built cavity), "field" (both refused, other fields), "false" (validate refused a
    design build accepted or failed on), "validate_failed" (validate neither accepted nor refused cleanly)."""
    v, b = r["validate"], r["status"]
    if v == "failed":
        return "validate_failed"
    if v == "refused":
        if b != "refused":
            return "false"
        return "agree" if r["validate_detail"] == r["detail"] else "field"
    return "late" if b == "refused" else "agree"


def refusal_seconds(r):
    """Time of the refusing command: validate's when it refused, else build's."""
    return r["validate_seconds"] if r["validate"] == "refused" else r["seconds"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", required=True)
    ap.add_argument("--count", type=int, default=200)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=len(os.sched_getaffinity(0)))
    ap.add_argument("--light", action="store_true")
    ap.add_argument("--timeout", type=float, default=900)
    ap.add_argument("--keep", help="keep the variants' configs and outputs in this directory")
    ap.add_argument("--min-built", type=float, default=0.0,
                    help="exit 1 when fewer than this fraction of the variants built (CI: 0.5)")
    ap.add_argument("--show-refusals", action="store_true", help="print the message of every refusal inside the ranges")
    a = ap.parse_args()
    rng = random.Random(a.seed)
    designs = []
    for i in range(a.count):
        inside = i % 2 == 0
        base = "c3x" if i % 4 in (1, 2) else "rotor"
        doc = (vary_c3x if base == "c3x" else vary_rotor)(rng, inside, a.light)
        if base == "c3x":  # a vane is fed through either end wall; its own stream keeps the other draws
            feed_ends(doc, random.Random("%d/%d" % (a.seed, i)))
        doc["name"] = "random_%03d" % i
        designs.append((i, base, inside, doc))
    work = a.keep or tempfile.mkdtemp(prefix="cg_random_designs_")
    os.makedirs(work, exist_ok=True)
    results = {}
    threads = max(1, len(os.sched_getaffinity(0)) // a.jobs)  # as coolinggen sweep shares the CPUs
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        futures = {pool.submit(run_variant, a.binary, work, i, copy.deepcopy(doc), a.timeout, threads): (i, base, inside)
                   for i, base, inside, doc in designs}
        for f in concurrent.futures.as_completed(futures):
            i, base, inside = futures[f]
            r = f.result()
            r.update(base=base, inside=inside)
            results[i] = r
            if a.keep:  # each result as it comes, so a stopped run still leaves what it measured
                with open(os.path.join(work, "results.jsonl"), "a") as log:
                    log.write(json.dumps(r) + "\n")
    rows = [results[i] for i in sorted(results)]
    if not a.keep:
        shutil.rmtree(work, ignore_errors=True)

    def counts(sel):
        c = {"built": 0, "refused": 0, "failed": 0}
        for r in sel:
            c[r["status"]] += 1
        return c
    allc, insc = counts(rows), counts([r for r in rows if r["inside"]])
    print("random designs: %d variants (seed %d%s, %d at a time on %d threads each), %d built, %d refused, %d failed" %
          (len(rows), a.seed, ", light" if a.light else "", a.jobs, threads, allc["built"], allc["refused"], allc["failed"]))
    n_in = sum(insc.values())
    print("  inside the stated ranges: %d of %d built (%.0f %%; goal >= 90 %%), %d refused, %d failed" %
          (insc["built"], n_in, 100.0 * insc["built"] / max(1, n_in), insc["refused"], insc["failed"]))
    for base in ("rotor", "c3x"):
        c = counts([r for r in rows if r["base"] == base])
        print("  %-5s %d built, %d refused, %d failed" % (base, c["built"], c["refused"], c["failed"]))
    reasons = {}
    for r in rows:
        if r["status"] == "refused":
            reasons.setdefault(field_group(r["detail"]), []).append(r["index"])
    if reasons:
        print("  refusals by field:")
        for k, v in sorted(reasons.items(), key=lambda kv: -len(kv[1])):
            print("    %3d  %s" % (len(v), k))
    built = [r["seconds"] for r in rows if r["status"] == "built"]
    refused_rows = [r for r in rows if r["status"] == "refused"]
    refused = [refusal_seconds(r) for r in refused_rows]
    if built and refused:
        mb = statistics.median(built)
        print("  time to refusal / median build time (%.1f s): median %.3f, worst %.3f (goal <= 0.05)" %
              (mb, statistics.median(refused) / mb, max(refused) / mb))
    kinds = {}
    for r in rows:
        kinds.setdefault(agreement(r), []).append(r)
    by_validate = [r for r in refused_rows if r["validate"] == "refused"]
    print("  validate vs build: %d of %d refused variants refused by validate naming the same field; "
          "disagreements %d (goal 0): %d late refusals (validate valid, build refused), %d other field, "
          "%d refused by validate only, %d validate failed" %
          (sum(1 for r in refused_rows if agreement(r) == "agree"), len(refused_rows), sum(len(kinds.get(k, [])) for k in ("late", "field", "false", "validate_failed")),
           len(kinds.get("late", [])), len(kinds.get("field", [])), len(kinds.get("false", [])),
           len(kinds.get("validate_failed", []))))
    if by_validate:
        vs = [r["validate_seconds"] for r in by_validate]
        print("  validate's refusals: median %.2f s, worst %.2f s" % (statistics.median(vs), max(vs)))
    if built and kinds.get("late"):
        late = [r["seconds"] for r in kinds["late"]]
        print("  late refusals / median build time: median %.3f, worst %.3f" %
              (statistics.median(late) / mb, max(late) / mb))
    for k in ("late", "field", "false", "validate_failed"):
        for r in kinds.get(k, []):
            print("  DISAGREE (%s) v%03d (%s, %s): validate %s %s in %.2f s; build %s in %.1f s: %s" %
                  (k, r["index"], r["base"], "inside" if r["inside"] else "free", r["validate"], r["validate_detail"],
                   r["validate_seconds"], r["status"], r["seconds"], (r["message"] or r["detail"])[:300]))
    for r in rows:
        if a.show_refusals and r["status"] == "refused" and r["inside"]:
            print("  refused v%03d (%s, inside): %s" % (r["index"], r["base"], r["message"][:400]))
        if r["status"] == "failed":
            print("  FAILED v%03d (%s, %s): %s" % (r["index"], r["base"], "inside" if r["inside"] else "free", r["detail"]))
    if allc["built"] < a.min_built * len(rows):
        print("  TOO FEW BUILT: %d of %d, fewer than --min-built %.2f" % (allc["built"], len(rows), a.min_built))
        return 1
    return 1 if allc["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
