#!/usr/bin/python3
"""liggghts-rigidsurf is a drop-in for Debian's liggghts.

A stock LIGGGHTS tutorial (heatTransfer_1 from liggghts-doc: insertion, granular pair
style with heat conduction, primitive walls, thermo output and VTK dumps) runs unchanged
with both executables, on the same command line. The screen output agrees line by line
once run times and dates are set aside, and every dump file is byte-for-byte the same.
"""
import filecmp
import os
import shutil
import subprocess

import liglib as L

TUTORIAL = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public/heatTransfer_1"
REFERENCE = "/usr/bin/liggghts"
# Lines that report run time, dates or memory: they differ between any two runs.
TIMING = ("time", "Setting up run at", "Memory usage", "Loop time", "%", "Total wall")


def comparable(text):
    return [l for l in text.splitlines() if not any(t in l for t in TIMING)]


def body(s):
    ck = s.ck
    if not ck.check("stock tutorial present", os.path.isdir(TUTORIAL), TUTORIAL,
                    "install liggghts-doc (tools/setup-deps does)"):
        return
    outs = {}
    for tag, exe in (("liggghts", REFERENCE), ("liggghts-rigidsurf", s.exe)):
        d = os.path.join(s.dir, tag)
        shutil.copytree(TUTORIAL, d)
        os.makedirs(os.path.join(d, "post"), exist_ok=True)
        p = subprocess.run(["stdbuf", "-o0", exe, "-in", "in.heatGran", "-echo", "screen"],
                           cwd=d, capture_output=True, text=True, errors="replace", timeout=240)
        ck.check("%s runs the tutorial" % tag, p.returncode == 0, "exit %d" % p.returncode,
                 "\n".join((p.stdout + p.stderr).splitlines()[-10:]))
        outs[tag] = (d, p.stdout + p.stderr)
    (dref, oref), (dours, oours) = outs["liggghts"], outs["liggghts-rigidsurf"]
    a, b = comparable(oref), comparable(oours)
    first = next((i for i, (x, y) in enumerate(zip(a, b)) if x != y), min(len(a), len(b)))
    ck.check("screen output identical apart from times", a == b and len(a) > 50,
             "%d lines compared" % len(a),
             "first difference at line %d: %r vs %r" % (first, a[first] if first < len(a) else "",
                                                        b[first] if first < len(b) else ""))
    dumps = sorted(os.listdir(os.path.join(dref, "post")))
    same = [f for f in dumps if os.path.isfile(os.path.join(dours, "post", f)) and
            filecmp.cmp(os.path.join(dref, "post", f), os.path.join(dours, "post", f), shallow=False)]
    ck.check("dump files byte-for-byte identical", dumps and len(same) == len(dumps),
             "%d of %d files" % (len(same), len(dumps)))
    log_a = open(os.path.join(dref, "log.liggghts")).read()
    log_b = open(os.path.join(dours, "log.liggghts")).read()
    ck.check("log.liggghts identical apart from times", comparable(log_a) == comparable(log_b))


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
