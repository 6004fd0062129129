"""coolinggen.study (issue 23): a 12-variant study of a light config run on a dask.distributed LocalCluster
of 2 workers, each variant a task running the CLI in a subprocess, gives the table of the serial
`coolinggen sweep` (same status and metrics per variant; build_s and process_s, wall times, excepted), each
build on its worker's one thread (report.json "threads").

Usage: python3 test_study.py CLI"""
import json
import os
import subprocess
import sys
import tempfile

from dask.distributed import Client, LocalCluster

import coolinggen
import coolinggen.study
from checks import check, finish
from light_configs import light_blade

CLI = sys.argv[1]


def rows_of(table):
    return table.to_dict("records") if hasattr(table, "to_dict") else table


def without_times(rows):
    return [{k: v for k, v in row.items() if k not in ("build_s", "process_s")} for row in rows]


def main():
    """Under __main__ only: Dask's worker processes import this module again (spawn)."""
    with tempfile.TemporaryDirectory() as tmp:
        # 3 spans x 4 thicknesses; 50 mm on the 38 mm chord is refused by the config check (no process).
        study = {"name": "light_grid", "base": light_blade(),
                 "parameters": [{"name": "span", "path": "flow_path.span", "values": [10, 20, 30]},
                                {"name": "thickness", "path": "sections[0].parametric.max_thickness",
                                 "values": [8, 12, 16, 50]}],
                 "design": {"type": "grid"}}
        path = os.path.join(tmp, "study.json")
        with open(path, "w") as f:
            json.dump(study, f)
        serial = os.path.join(tmp, "serial")
        r = subprocess.run([CLI, "sweep", path, "-o", serial, "--jobs", "1", "-q"], capture_output=True, text=True)
        check(r.returncode == 0, r.stderr)
        expected = rows_of(coolinggen.study.read_results(os.path.join(serial, "results.csv")))
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
                Client(cluster) as client:
            table = coolinggen.study.run(path, os.path.join(tmp, "dask"), client, cli=CLI)
        rows = rows_of(table)
        check(len(rows) == 12, f"{len(rows)} rows")
        check(without_times(rows) == without_times(expected), "the Dask table differs from the serial sweep's")
        statuses = [row["status"] for row in rows]
        check(statuses.count("built") == 9 and statuses.count("refused") == 3, f"statuses {statuses}")
        check(all(row["solid_volume_mm3"] > 0 for row in rows if row["status"] == "built"), "volumes")
        for row in rows:  # each build on its worker's one thread
            if row["status"] == "built":
                with open(os.path.join(tmp, "dask", "variants", str(row["id"]), "report.json")) as f:
                    check(json.load(f)["threads"] == 1, f"variant {row['id']} not on its worker's one thread")
        pids = {pid for _, _, _, pid in coolinggen.study.run.last_tasks}
        check(len(pids) == 2, f"tasks ran in {len(pids)} worker processes")
        print(f"{len(rows)} variants on 2 Dask workers: {statuses.count('built')} built, "
              f"{statuses.count('refused')} refused, table equal to the serial sweep's")
        # An invalid study is the CLI's one-line error as ConfigError.
        study["parameters"][0]["path"] = "flow_path.spam"
        with open(path, "w") as f:
            json.dump(study, f)
        try:
            coolinggen.study.run(path, os.path.join(tmp, "bad"), cli=CLI)
            check(False, "invalid study accepted")
        except coolinggen.ConfigError as e:
            check(str(e).startswith("parameters[0].path: "), str(e))


if __name__ == "__main__":
    main()
    finish()
