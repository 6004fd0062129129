"""Design studies on a dask.distributed cluster: the study file of `coolinggen sweep` (docs/studies.md),
each variant one task that runs the CLI in a subprocess (a crash of OCCT ends that process, not the
worker), the results gathered into the table of the serial `coolinggen sweep`.

    from dask.distributed import Client, LocalCluster
    import coolinggen.study
    with Client(LocalCluster(n_workers=2, threads_per_worker=1)) as client:
        table = coolinggen.study.run("study.json", "out/study", client)

How: `coolinggen sweep STUDY -o DIR --emit slurm` expands and checks the variants and writes their
configs (DIR/variants/<id>/config.json); each task runs `coolinggen sweep STUDY -o DIR --only <id>
--jobs 1 --threads T` (T: its worker's threads), which builds one variant and writes its status.json and report.json (never results.csv, so
tasks do not race); `coolinggen sweep --collect DIR` then writes DIR/results.csv, read back here. DIR must
be on a file system every worker sees. The table is a pandas DataFrame when pandas is installed, else a
list of dicts, one per variant in design order; numbers are ints or floats, empty cells None.
"""
import csv
import os
import re
import shutil
import subprocess

from . import ConfigError, Error


def find_cli(cli=None):
    """The coolinggen executable: `cli`, $COOLINGGEN_CLI, the prefix's bin/coolinggen of an installed
    package (<prefix>/lib/python3/dist-packages/coolinggen), or coolinggen on PATH."""
    here = os.path.dirname(os.path.abspath(__file__))
    candidates = [cli, os.environ.get("COOLINGGEN_CLI"),
                  os.path.normpath(os.path.join(here, "..", "..", "..", "..", "bin", "coolinggen")),
                  shutil.which("coolinggen")]
    for c in candidates:
        if c and os.path.isfile(c) and os.access(c, os.X_OK):
            return c
    raise Error("the coolinggen executable was not found: pass cli= or set COOLINGGEN_CLI")


def _cli_error(r):
    """The CLI's one-line error as the matching exception (exit 2: ConfigError, naming the study field)."""
    message = r.stderr.strip().removeprefix("coolinggen: error: ")
    return ConfigError(message) if r.returncode == 2 else Error(message or f"exit code {r.returncode}")


def _worker_threads():
    """The threads of the dask worker running this task (its share of the machine: LocalCluster's
    threads_per_worker), None outside a worker."""
    try:
        from distributed import get_worker
        return get_worker().nthreads
    except (ImportError, ValueError):
        return None


def _run_variant(cli, study, directory, variant, timeout):
    """One task: builds `variant` by `coolinggen sweep --only` in a subprocess, on the worker's threads;
    (id, exit code, pid)."""
    args = [cli, "sweep", study, "-o", directory, "--only", variant, "--jobs", "1", "-q"]
    if timeout:
        args += ["--timeout", str(timeout)]
    threads = _worker_threads()
    if threads:
        args += ["--threads", str(threads)]
    r = subprocess.run(args, capture_output=True, text=True)
    return variant, r.returncode, r.stderr.strip(), os.getpid()


def _cell(column, text):
    if text == "":
        return None
    if column != "id" and re.fullmatch(r"-?[0-9]+", text):
        return int(text)
    try:
        return float(text) if column != "id" else text
    except ValueError:
        return text


def read_results(path):
    """results.csv of `coolinggen sweep` as the table run() returns."""
    with open(path, newline="") as f:
        rows = [{k: _cell(k, v) for k, v in row.items()} for row in csv.DictReader(f)]
    try:
        import pandas
    except ImportError:
        return rows
    return pandas.DataFrame(rows)


def run(study, directory, client=None, timeout=None, cli=None):
    """Runs the study file `study` into `directory` with one task per variant on the dask.distributed
    `client` (None: one after the other here) and returns the results table (read_results). timeout:
    seconds per variant build (its status is then "timeout"). Raises ConfigError for an invalid study
    (the CLI's message, naming the study field), Error when a task's CLI failed otherwise."""
    cli = find_cli(cli)
    study, directory = os.path.abspath(os.fspath(study)), os.path.abspath(os.fspath(directory))
    r = subprocess.run([cli, "sweep", study, "-o", directory, "--emit", "slurm", "-q"], capture_output=True, text=True)
    if r.returncode != 0:
        raise _cli_error(r)
    variants = sorted(os.listdir(os.path.join(directory, "variants")))
    if client is None:
        done = [_run_variant(cli, study, directory, v, timeout) for v in variants]
    else:
        futures = client.map(_run_variant, [cli] * len(variants), [study] * len(variants),
                             [directory] * len(variants), variants, [timeout] * len(variants), pure=False)
        done = client.gather(futures)
    run.last_tasks = done  # (id, exit code, stderr, pid) per variant, for inspection
    for variant, code, err, _ in done:
        if code not in (0, 6):  # a variant's own failure is a status in its row; this is the CLI's
            raise Error(f"variant {variant}: coolinggen sweep --only exited {code}: {err}")
    r = subprocess.run([cli, "sweep", "--collect", directory, "-q"], capture_output=True, text=True)
    if r.returncode != 0:
        raise _cli_error(r)
    return read_results(os.path.join(directory, "results.csv"))
