#!/usr/bin/python3
"""lmp-rigidsurf runs stock LAMMPS decks as Debian's lmp does, and takes lmp's command line.

The granular examples of Debian's lammps-examples (granregion box and funnel, granular
pour.drum, pour) run with every `run N` cut to 300 steps, in stock lmp and in
lmp-rigidsurf: their thermo tables are the same, character for character (less the
columns of elapsed time). lmp-rigidsurf -h prints lmp's help (LAMMPS prints it and exits
while it is made, before the styles are added, so wall/rigid is not in its lists); an
unknown command line option is LAMMPS's own error.
"""
import os
import re
import shutil
import subprocess

import lmplib as M

EXAMPLES = "/usr/share/lammps/examples"
DECKS = ["granregion/in.granregion.box", "granregion/in.granregion.funnel",
         "granular/in.pour.drum", "pour/in.pour"]


TIMES = {"CPU", "CPULeft", "TPS", "KTPS", "SPCPU", "CPURemain", "Elapsed"}


def thermo(out):
    """The thermo tables of a run's output (the lines from each 'Step' header to 'Loop
    time'), less the columns of elapsed time, which differ from run to run."""
    rows, keep = [], None
    for line in out.splitlines():
        w = line.split()
        if w[:1] == ["Step"]:
            keep = [k for k, c in enumerate(w) if c not in TIMES]
        elif line.startswith("Loop time"):
            keep = None
        if keep is not None:
            rows.append(" ".join(w[k] for k in keep if k < len(w)))
    return rows


def body(s):
    for rel in DECKS:
        src = os.path.join(EXAMPLES, rel)
        text = re.sub(r"(?m)^(\s*run\s+)\d+", r"\g<1>300", open(src).read())
        name = os.path.basename(rel).replace("in.", "").replace(".", "_")
        tables = {}
        for tag, exe in (("stock", s.args.lmp), ("rigid", s.exe)):
            d = os.path.join(s.dir, name + "_" + tag)
            os.makedirs(d)
            for f in os.listdir(os.path.dirname(src)):
                shutil.copy(os.path.join(os.path.dirname(src), f), d)
            with open(os.path.join(d, "in.test"), "w") as f:
                f.write(text)
            rc, out = s.run(os.path.join(name + "_" + tag, "run"), text, exe=exe)
            tables[tag] = thermo(out)
        s.ck.check("%s: a thermo table of the stock run" % name, len(tables["stock"]) >= 3,
                   "%d lines" % len(tables["stock"]))
        s.ck.check("%s: lmp-rigidsurf's thermo table is stock's, character for character"
                   % name, tables["rigid"] == tables["stock"],
                   "%d lines" % len(tables["rigid"]))
    out = subprocess.run([s.exe, "-h"], capture_output=True, text=True).stdout
    stock = subprocess.run([s.args.lmp, "-h"], capture_output=True, text=True).stdout
    s.ck.check("-h: lmp's help (its usage line names the executable)",
               out.replace(s.exe, s.args.lmp) == stock and "29 Sep 2021" in out)
    p = subprocess.run([s.exe, "-bogus"], capture_output=True, text=True)
    s.ck.check("an unknown option: LAMMPS's error", p.returncode == 1
               and "Invalid command-line argument" in p.stdout + p.stderr)


if __name__ == "__main__":
    M.L.main_guard(M.L.Session(__doc__, extra=[M.STOCK]), body)
