#!/usr/bin/env python3
"""pecplas-sweep: parameter studies with pecplas (doc/sweep.md).

    pecplas-sweep make TEMPLATE TABLE -o DIR      one deck per table row: DIR/<case>.inp
    pecplas-sweep run DIR [-j N]                  run them locally, N at a time; each case's
                                                  start, progress and end on one line each
    pecplas-sweep slurm DIR [--partition P ...]   write DIR/sweep.sbatch, a Slurm job array
    pecplas-sweep collect DIR -q NAME=QUANTITY ...    gather quantities -> DIR/collected.{csv,h5}

The template is a deck with `{{NAME}}` placeholders; the table is a CSV file (header = names,
one row per case) or a TOML file with one `[[case]]` table per row. A column `case` (optional)
names the case; otherwise cases are case_000, case_001, ... Relative `FILE=` paths of the
template (*INCLUDE, *MESH, *OUTPUT) are rewritten so that the decks written to DIR find the
same files. Python standard library only, plus h5py and numpy for `collect`.
Exit codes: 0 done, 1 some run failed, 2 bad input (message `file:line: what was expected`).
"""
import argparse
import csv
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

PLACEHOLDER = re.compile(r"\{\{\s*([A-Za-z_][A-Za-z0-9_]*)\s*\}\}")
FILE_OPTION = re.compile(r"(FILE\s*=\s*)([^,\s]+)", re.IGNORECASE)
MANIFEST = "sweep.json"
CASE_NAME = re.compile(r"^[A-Za-z0-9_.+-]+$")
# exit codes of pecplas that leave a results file: completed, stopped early (limit load...)
RESULT_CODES = (0, 3)


class InputError(Exception):
    """Bad input: the message is `file:line: text` and the program exits with 2."""


# ---------------------------------------------------------------- make
def read_table(path):
    """List of (case name, {column: text}) from a CSV or TOML table."""
    path = Path(path)
    if not path.is_file():
        raise InputError(f"{path}: no such table file (CSV or TOML expected)")
    rows = []
    if path.suffix.lower() == ".toml":
        import tomllib
        try:
            data = tomllib.loads(path.read_text())
        except tomllib.TOMLDecodeError as e:
            raise InputError(f"{path}:1: [TOML] {e}") from None
        cases = data.get("case")
        if not isinstance(cases, list) or not cases:
            raise InputError(f"{path}:1: [TOML] expected one or more [[case]] tables")
        for i, c in enumerate(cases):
            rows.append((i + 2, {str(k): _toml_text(v) for k, v in c.items()}))
    else:
        with path.open(newline="") as f:
            lines = [ln for ln in f if ln.strip() and not ln.lstrip().startswith("#")]
        reader = csv.reader(lines)
        header = [h.strip() for h in next(reader, [])]
        if not header or any(not h for h in header):
            raise InputError(f"{path}:1: [CSV] expected a header line of column names")
        for n, rec in enumerate(reader, start=2):
            if len(rec) != len(header):
                raise InputError(f"{path}:{n}: [CSV] expected {len(header)} values "
                                 f"({', '.join(header)}), found {len(rec)}")
            rows.append((n, {h: v.strip() for h, v in zip(header, rec)}))
    if not rows:
        raise InputError(f"{path}:2: [TABLE] expected at least one row of values")
    cases, seen = [], set()
    for i, (line, values) in enumerate(rows):
        name = values.pop("case", None) or f"case_{i:03d}"
        if not CASE_NAME.match(name):
            raise InputError(f"{path}:{line}: [TABLE] case name {name!r}: expected letters, "
                             "digits, '_', '-', '.', '+' only")
        if name in seen:
            raise InputError(f"{path}:{line}: [TABLE] case name {name!r} given twice")
        seen.add(name)
        cases.append((line, name, values))
    return cases


def _toml_text(v):
    if isinstance(v, bool):
        return "YES" if v else "NO"
    return repr(v) if isinstance(v, float) else str(v)


def substitute(template_path, text, values, table_path, line):
    """Template text with every {{NAME}} replaced; unknown names are an input error."""
    out = []
    for n, src in enumerate(text.splitlines(keepends=True), start=1):
        def repl(m):
            if m.group(1) not in values:
                raise InputError(f"{template_path}:{n}: [TEMPLATE] placeholder {{{{{m.group(1)}}}}}"
                                 f" has no column in {table_path} (columns: "
                                 f"{', '.join(sorted(values)) or 'none'})")
            return values[m.group(1)]
        out.append(PLACEHOLDER.sub(repl, src))
    return "".join(out)


def rebase_files(text, template_dir, out_dir):
    """Relative FILE= paths on keyword lines, made relative to out_dir instead of template_dir."""
    lines = []
    for ln in text.splitlines(keepends=True):
        if ln.lstrip().startswith("*") and not ln.lstrip().startswith("**"):
            def repl(m):
                p = m.group(2)
                if os.path.isabs(p):
                    return m.group(0)
                target = (template_dir / p).resolve()
                return m.group(1) + os.path.relpath(target, out_dir.resolve())
            ln = FILE_OPTION.sub(repl, ln)
        lines.append(ln)
    return "".join(lines)


def cmd_make(a):
    template, table, out = Path(a.template), Path(a.table), Path(a.output)
    if not template.is_file():
        raise InputError(f"{template}: no such template deck")
    text = template.read_text()
    used = set(PLACEHOLDER.findall(text))
    if not used:
        raise InputError(f"{template}:1: [TEMPLATE] expected at least one {{{{NAME}}}} placeholder")
    cases = read_table(table)
    out.mkdir(parents=True, exist_ok=True)
    manifest = {"template": str(template.resolve()), "table": str(table.resolve()), "cases": []}
    for line, name, values in cases:
        deck = substitute(template, text, values, table, line)
        deck = rebase_files(deck, template.parent, out)
        header = (f"** {name}: written by pecplas-sweep from {template} with "
                  + ", ".join(f"{k} = {v}" for k, v in values.items()) + "\n")
        (out / f"{name}.inp").write_text(header + deck)
        manifest["cases"].append({"name": name, "deck": f"{name}.inp",
                                  "results": f"{name}.h5", "parameters": values})
    unused = sorted(set(cases[0][2]) - used)
    (out / MANIFEST).write_text(json.dumps(manifest, indent=1) + "\n")
    print(f"pecplas-sweep: {len(cases)} decks written to {out}")
    if unused:
        print(f"pecplas-sweep: note: column(s) {', '.join(unused)} of {table} are used by no "
              "placeholder", file=sys.stderr)
    return 0


# ---------------------------------------------------------------- run / slurm
def load_manifest(d):
    p = Path(d) / MANIFEST
    if not p.is_file():
        raise InputError(f"{p}: no sweep here (expected the directory written by "
                         "`pecplas-sweep make`)")
    return json.loads(p.read_text())


def pecplas_cmd_command(given):
    """The pecplas executable: --pecplas, $PECPLAS_BIN, next to this script, or on PATH."""
    for c in (given, os.environ.get("PECPLAS_BIN")):
        if c:
            return str(Path(c).resolve()) if Path(c).exists() else c
    here = Path(__file__).resolve().parent / "pecplas"
    if here.is_file():
        return str(here)
    found = shutil.which("pecplas")
    if not found:
        raise InputError("pecplas: not found (give --pecplas PATH, set PECPLAS_BIN or put "
                         "pecplas on PATH, e.g. `make install`)")
    return found


INCREMENT_LINE = re.compile(r"^\s*step\s+(\d+)\s+(.*?)\s+inc\s+(\d+)\s+fraction\s+(\S+)")


class Reporter:
    """The runner's lines, one per event of a case, never interleaved: its start, its
    progress (pecplas's own `progress:` line, or its latest increment, at most every
    `interval` seconds; 0: each one; negative: none) and its end."""

    def __init__(self, total, interval):
        self.total, self.interval = total, interval
        self.done = 0
        self.lock = threading.Lock()

    def say(self, text):
        with self.lock:
            print(f"pecplas-sweep: {text}", flush=True)

    def end(self, text):
        with self.lock:
            self.done += 1
            print(f"pecplas-sweep: {text} [{self.done} of {self.total} done]", flush=True)


def progress_of(line):
    """What a line of pecplas's output says about its progress (None: nothing)."""
    text = line.strip()
    if text.startswith("progress:"):
        return text[len("progress:"):].strip()
    m = INCREMENT_LINE.match(line)
    if m:
        return f"step {m.group(1)} '{m.group(2)}', increment {m.group(3)}, fraction " \
               f"{float(m.group(4)):g} of the step"
    return None


def run_case(exe, d, case, number, report):
    """Runs one case, its output into DIR/<case>.log, its start, progress and end reported."""
    deck, res, name = case["deck"], case["results"], case["name"]
    tag = f"[{number}/{report.total}] {name}"
    report.say(f"{tag} started ({deck} -> {res})")
    status = None
    t0 = time.monotonic()
    last = None
    with open(d / f"{name}.log", "w") as log:
        # not --quiet: its increment and progress lines are the case's progress
        p = subprocess.Popen([exe, deck, "-o", res], cwd=d, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True, errors="replace")
        for line in p.stdout:
            log.write(line)
            if line.strip().startswith("status:"):
                status = line.split("status:", 1)[1].split("results:")[0].strip()
            what = progress_of(line) if report.interval >= 0 else None
            now = time.monotonic()
            if what and (last is None and now - t0 >= report.interval
                         or last is not None and now - last >= report.interval):
                last = now
                report.say(f"{tag} {now - t0:.1f} s: {what}")
        rc = p.wait()
    t = time.monotonic() - t0
    ok = rc in RESULT_CODES
    report.end(f"{tag} exit {rc} ({status or 'no status'}, {t:.1f} s)"
               + ("" if ok else f", see {d / (name + '.log')}"))
    return name, rc, t


def cmd_run(a):
    d = Path(a.dir)
    m = load_manifest(d)
    exe = pecplas_cmd_command(a.pecplas)
    cases = m["cases"]
    if a.cases:
        cases = [cases[i] for i in a.cases]
    report = Reporter(len(cases), a.progress)
    bad = 0
    with ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
        for name, rc, t in pool.map(lambda ic: run_case(exe, d, ic[1], ic[0] + 1, report),
                                    enumerate(cases)):
            bad += rc not in RESULT_CODES
    return 1 if bad else 0


SBATCH = """#!/bin/bash
# Written by pecplas-sweep: one array task per deck of {dir}.
#   sbatch {script}      then, when all tasks are done: pecplas-sweep collect {dir} -q ...
#SBATCH --job-name={job}
#SBATCH --array=0-{last}{throttle}
#SBATCH --ntasks=1
#SBATCH --cpus-per-task={cpus}
#SBATCH --output={dir}/slurm-%A_%a.out
{extra}set -uo pipefail
cases=({cases})
case=${{cases[$SLURM_ARRAY_TASK_ID]}}
cd {dir}
export OMP_NUM_THREADS=${{SLURM_CPUS_PER_TASK:-1}}
{exe} "$case.inp" -o "$case.h5" --quiet >"$case.log" 2>&1
rc=$?
echo "$case exit $rc" >>"$case.log"
# 3 = stopped early (limit load, divergence): the results file is complete up to there
[[ $rc == 0 || $rc == 3 ]] || exit $rc
"""


def cmd_slurm(a):
    d = Path(a.dir).resolve()
    m = load_manifest(d)
    n = len(m["cases"])
    extra = ""
    for opt in ("partition", "time", "account", "mem"):
        v = getattr(a, opt)
        if v:
            extra += f"#SBATCH --{opt}={v}\n"
    script = d / "sweep.sbatch"
    script.write_text(SBATCH.format(
        dir=shlex.quote(str(d)), script=shlex.quote(str(script)), job=a.job_name, last=n - 1,
        throttle=f"%{a.max_parallel}" if a.max_parallel else "", cpus=a.cpus_per_task,
        extra=extra, cases=" ".join(shlex.quote(c["name"]) for c in m["cases"]),
        exe=shlex.quote(pecplas_cmd_command(a.pecplas))))
    script.chmod(0o755)
    print(f"pecplas-sweep: {script} ({n} array tasks 0-{n - 1})")
    if a.submit:
        out = subprocess.run(["sbatch", "--parsable", str(script)], capture_output=True,
                             text=True)
        if out.returncode != 0:
            print(f"pecplas-sweep: sbatch failed: {out.stderr.strip()}", file=sys.stderr)
            return 1
        print(f"pecplas-sweep: submitted job {out.stdout.strip()}")
    return 0


# ---------------------------------------------------------------- collect
QUANTITY = re.compile(r"^(?:(max|min|last):)?(factor|disp|reaction):([^@]+?)(?:@(.+)=(.+))?$")


def parse_quantity(text):
    """NAME=[max:|min:|last:]KIND:ARGS[@PATTERN=VALUE] -> dict; see doc/sweep.md."""
    if "=" not in text:
        raise InputError(f"--quantity {text}: expected NAME=QUANTITY")
    name, spec = text.split("=", 1)
    m = QUANTITY.match(spec.strip())
    if not name.strip() or not m:
        raise InputError(f"--quantity {text}: expected NAME=[max:|min:]factor:PATTERN, "
                         "NAME=...disp:X,Y:x|y or NAME=...reaction:NSET:x|y, optionally "
                         "@PATTERN=VALUE")
    op, kind, args, at_pat, at_val = m.groups()
    q = {"name": name.strip(), "op": op or "last", "kind": kind, "at": None}
    if kind == "factor":
        q["pattern"] = args
    else:
        parts = args.split(":")
        # the deck's dof words: x, r, 1 (first dof), y, z, 2 (second), any letter case
        dof = {"x": 0, "r": 0, "1": 0, "y": 1, "z": 1, "2": 1}.get(parts[-1].strip().lower())
        if len(parts) != 2 or dof is None:
            raise InputError(f"--quantity {text}: expected {kind}:{'X,Y' if kind == 'disp' else 'NSET'}"
                             ":x or :y (r, z, 1, 2 too)")
        q["where"], q["dir"] = parts[0], dof
        if kind == "disp":
            try:
                q["where"] = [float(v) for v in parts[0].split(",")]
                assert len(q["where"]) == 2
            except (ValueError, AssertionError):
                raise InputError(f"--quantity {text}: expected the node as X,Y") from None
    if at_pat:
        if q["op"] != "last":
            raise InputError(f"--quantity {text}: @PATTERN=VALUE goes with no max:/min:")
        try:
            q["at"] = (at_pat, float(at_val))
        except ValueError:
            raise InputError(f"--quantity {text}: expected a number after {at_pat}=") from None
    return q


def _text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def evaluate(path, quantities):
    """{name: value or None (not reached)}, status of the results file `path`."""
    import h5py
    import numpy as np
    with h5py.File(path, "r") as f:
        status = _text(f.attrs["status"])
        patterns = [_text(p) for p in np.atleast_1d(f["history"].attrs["patterns"])]
        fields = f["history/fields"][:].astype(bool)
        factors = f["history/pattern_factors"][:]
        factors = factors.reshape(len(fields), -1)
        gi = f["history/global_increment"][:]
        keys = [f"{int(g):06d}" for g in gi[fields]]
        fac = factors[fields]
        out = {}
        for q in quantities:
            def pat(name):
                if name not in patterns:
                    raise InputError(f"{path}: no load pattern {name!r} (patterns: "
                                     f"{', '.join(patterns)})")
                return patterns.index(name)
            if q["kind"] == "factor":
                series = fac[:, pat(q["pattern"])]
            elif q["kind"] == "disp":
                x = f["mesh/coordinates"][:]
                node = int(np.argmin(np.hypot(x[:, 0] - q["where"][0], x[:, 1] - q["where"][1])))
                series = np.array([f["increments"][k]["displacement"][node, q["dir"]]
                                   for k in keys])
            else:
                sets = {_text(g.attrs.get("name", k)): g for k, g in f["mesh/node_sets"].items()}
                if q["where"] not in sets:
                    raise InputError(f"{path}: no node set {q['where']!r} "
                                     f"(sets: {', '.join(sorted(sets))})")
                nodes = sets[q["where"]]["nodes"][:]
                series = np.array([f["increments"][k]["reaction"][:, q["dir"]][nodes].sum()
                                   for k in keys])
            out[q["name"]] = reduce(series, fac, q, pat)
    return out, status


def reduce(series, fac, q, pat):
    """The value of a quantity from its series over the written increments."""
    if len(series) == 0:
        return None
    if q["op"] == "max":
        return float(series.max())
    if q["op"] == "min":
        return float(series.min())
    if q["at"] is None:
        return float(series[-1])
    p = fac[:, pat(q["at"][0])]
    v = q["at"][1]
    for i in range(len(p)):
        if p[i] == v:
            return float(series[i])
        if i > 0 and (p[i - 1] - v) * (p[i] - v) < 0:
            w = (v - p[i - 1]) / (p[i] - p[i - 1])
            return float(series[i - 1] + w * (series[i] - series[i - 1]))
    return None


def cmd_collect(a):
    import h5py
    import numpy as np
    d = Path(a.dir)
    m = load_manifest(d)
    quantities = [parse_quantity(t) for t in a.quantity]
    params = list(dict.fromkeys(k for c in m["cases"] for k in c["parameters"]))
    rows, missing = [], 0
    for c in m["cases"]:
        res = d / c["results"]
        if res.is_file():
            try:
                values, status = evaluate(res, quantities)
            except (OSError, KeyError) as e:
                values, status = {}, f"unreadable ({e})"
        else:
            values, status = {}, "missing"
        missing += status in ("missing", "running") or status.startswith("unreadable")
        rows.append((c, status, values))
    csv_path = Path(a.output or d / "collected.csv")
    with csv_path.open("w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case"] + params + ["status"] + [q["name"] for q in quantities])
        for c, status, values in rows:
            w.writerow([c["name"]] + [c["parameters"].get(p, "") for p in params] + [status]
                       + ["" if values.get(q["name"]) is None else repr(values[q["name"]])
                          for q in quantities])
    h5_path = csv_path.with_suffix(".h5")
    with h5py.File(h5_path, "w") as f:
        f.attrs["sweep"] = str(d.resolve())
        f.attrs["quantities"] = json.dumps({q["name"]: t for q, t in zip(quantities, a.quantity)})
        f["case"] = [c["name"].encode() for c, _, _ in rows]
        f["status"] = [s.encode() for _, s, _ in rows]
        g = f.create_group("parameters")
        for p in params:
            vals = [c["parameters"].get(p, "") for c, _, _ in rows]
            try:
                g[p] = np.array([float(v) for v in vals])
            except ValueError:
                g[p] = [v.encode() for v in vals]
        g = f.create_group("quantities")
        for q in quantities:
            vals = [values.get(q["name"]) for _, _, values in rows]
            # never a NaN in a results file: a value not reached is 0 with found = 0
            g[q["name"]] = np.array([0.0 if v is None else v for v in vals])
            g[q["name"] + "_found"] = np.array([v is not None for v in vals], dtype=np.int8)
    print(f"pecplas-sweep: {len(rows)} cases collected into {csv_path} and {h5_path}"
          + (f" ({missing} without results)" if missing else ""))
    return 1 if missing else 0


# ---------------------------------------------------------------- command line
def main(argv=None):
    ap = argparse.ArgumentParser(prog="pecplas-sweep", description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="command", required=True)
    p = sub.add_parser("make", help="one deck per table row")
    p.add_argument("template")
    p.add_argument("table")
    p.add_argument("-o", "--output", required=True, help="directory for the decks")
    p.set_defaults(func=cmd_make)
    p = sub.add_parser("run", help="run the decks locally")
    p.add_argument("dir")
    p.add_argument("-j", "--jobs", type=int, default=1, help="runs at a time (default 1)")
    p.add_argument("--pecplas", help="pecplas executable")
    p.add_argument("--cases", type=int, nargs="+", help="only these case indices")
    p.add_argument("--progress", type=float, default=30.0, metavar="SECONDS",
                   help="a progress line per running case at most every SECONDS (default 30; "
                        "0: at every increment; negative: none)")
    p.set_defaults(func=cmd_run)
    p = sub.add_parser("slurm", help="write a Slurm job-array script")
    p.add_argument("dir")
    p.add_argument("--partition")
    p.add_argument("--time", help="wall time per task, e.g. 01:00:00")
    p.add_argument("--account")
    p.add_argument("--mem", help="memory per task, e.g. 2G")
    p.add_argument("--cpus-per-task", type=int, default=1)
    p.add_argument("--max-parallel", type=int, help="at most this many tasks at once (%%N)")
    p.add_argument("--job-name", default="pecplas-sweep")
    p.add_argument("--pecplas", help="pecplas executable on the compute nodes")
    p.add_argument("--submit", action="store_true", help="also submit it with sbatch")
    p.set_defaults(func=cmd_slurm)
    p = sub.add_parser("collect", help="gather quantities into one CSV and one HDF5")
    p.add_argument("dir")
    p.add_argument("-q", "--quantity", action="append", required=True,
                   help="NAME=[max:|min:]factor:PATTERN | disp:X,Y:x|y | reaction:NSET:x|y"
                        "[@PATTERN=VALUE]")
    p.add_argument("-o", "--output", help="CSV file (default DIR/collected.csv; .h5 beside)")
    p.set_defaults(func=cmd_collect)
    a = ap.parse_args(argv)
    try:
        return a.func(a)
    except InputError as e:
        print(f"pecplas-sweep: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
