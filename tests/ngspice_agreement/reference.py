#!/usr/bin/env python3
"""Writes NAME.ref.csv, ngspice's answer for NAME.cir, for tests/it/ngspice_agreement.rs.

    python3 tests/ngspice_agreement/reference.py NAME [NAME ...]

ngspice runs the netlist with tighter settings than the netlist's own (reltol 1e-8, and a
maximum step of 1/20000 of the run), so that its error is far below what the test checks
(where it crawls at 1e-8, taking more than ten times the planned points or a minute, 1e-7); the
dense result is then thinned to the points that linear interpolation cannot do without (every
dropped point is within 1e-5 of the largest node swing of the interpolation between the kept
ones), which keeps the committed file small. Needs ngspice on the PATH; plain Python 3.
"""
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
THIN = 1e-5


PLANNED = 20000


def tightened(netlist: str, reltol: float) -> str:
    out = []
    for line in netlist.splitlines():
        low = line.lower()
        if low.startswith(".options"):
            line = re.sub(r"reltol=\S+", f"reltol={reltol:g}", line, flags=re.I)
        elif low.startswith(".tran"):
            fields = line.split()
            stop = float(fields[2])
            line = f".tran {stop / PLANNED!r} {stop!r} 0 {stop / PLANNED!r}"
        out.append(line)
    return "\n".join(out) + "\n"


def run(name: str) -> tuple[float, list[str], list[list[float]]]:
    netlist = open(os.path.join(HERE, name + ".cir")).read()
    nodes = re.search(r"wrdata\s+\S+\s+(.*)", netlist).group(1).split()
    names = [re.sub(r"v\((\w+)\)", r"v\1", n) for n in nodes]
    for reltol in (1e-8, 1e-7):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, name + ".cir")
            open(path, "w").write(tightened(netlist, reltol))
            # ngspice -b exits 1 after a .control block even when it ran: the data file
            # tells.
            try:
                subprocess.run(
                    ["ngspice", "-b", path], cwd=tmp, capture_output=True, timeout=60
                )
            except subprocess.TimeoutExpired:
                continue
            rows = []
            for line in open(os.path.join(tmp, name + ".txt")):
                fields = [float(v) for v in line.split()]
                rows.append([fields[0]] + fields[1::2])
        if len(rows) <= 10 * PLANNED:
            return reltol, names, rows
    sys.exit(f"{name}: ngspice crawls at reltol 1e-7 as well")


def thin(rows: list[list[float]]) -> list[list[float]]:
    ncol = len(rows[0])
    swing = max(
        max(r[c] for r in rows) - min(r[c] for r in rows) for c in range(1, ncol)
    )
    bound = THIN * max(swing, 1e-12)
    kept = [rows[0]]
    start = 0
    i = 1
    while i < len(rows):
        # Extend the segment from `start` while every point inside stays interpolable.
        j = i + 1
        if j < len(rows) and all(
            interpolable(rows, start, j, k, bound) for k in range(start + 1, j)
        ):
            i = j
            continue
        kept.append(rows[i])
        start = i
        i += 1
    if kept[-1] is not rows[-1]:
        kept.append(rows[-1])
    return kept


def interpolable(rows, a, b, k, bound) -> bool:
    ta, tb, tk = rows[a][0], rows[b][0], rows[k][0]
    if tb <= ta:
        return False
    w = (tk - ta) / (tb - ta)
    return all(
        abs(rows[a][c] + w * (rows[b][c] - rows[a][c]) - rows[k][c]) <= bound
        for c in range(1, len(rows[0]))
    )


def main() -> None:
    for name in sys.argv[1:]:
        reltol, names, rows = run(name)
        kept = thin(rows)
        with open(os.path.join(HERE, name + ".ref.csv"), "w") as f:
            f.write(
                f"# ngspice {name}.cir at reltol {reltol:g}, max step stop/{PLANNED} "
                "(reference.py)\n"
            )
            f.write(",".join(["time"] + names) + "\n")
            for r in kept:
                f.write(",".join(f"{v:.10g}" for v in r) + "\n")
        print(f"{name}: {len(rows)} points, {len(kept)} kept")


if __name__ == "__main__":
    main()
