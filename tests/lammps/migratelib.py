"""Helpers of the tests that run LAMMPS decks as rigidsurf-migrate rewrites them
(test_migrate_*.py): each takes lmplib's arguments and --migrate PATH/rigidsurf-migrate.

A pair: the deck as written runs in Debian's stock lmp, the deck as the tool rewrites it
in lmp-rigidsurf; both dump every sphere's position, velocity, spin, force and torque
with 17 digits, and the two dumps are compared.
"""
import os
import subprocess

import lmplib as M

MIGRATE = ("--migrate", "rigidsurf-migrate")


def session(doc):
    return M.L.Session(doc, extra=[M.STOCK, MIGRATE])


def migrate(s, name, deck, args=()):
    """Writes deck to NAME.in in the scratch directory and runs the tool on it: (exit
    status, the migrated deck, stderr)."""
    path = s.write(name + ".in", deck)
    p = subprocess.run([s.args.migrate, path] + list(args), capture_output=True, text=True,
                       timeout=120, cwd=s.dir)
    return p.returncode, p.stdout, p.stderr


def pair(s, name, deck, want_rc=0, dump=None):
    """Runs deck in stock lmp (NAME_stock) and as migrated in lmp-rigidsurf (NAME_rigid);
    deck's dump writes DUMP (default NAME.dump), renamed per run. Checks the tool's exit
    status; returns (stock frames, migrated frames, the tool's stderr, migrated deck)."""
    dump = dump or name + ".dump"
    rc, out, err = migrate(s, name, deck)
    s.ck.check("%s: rigidsurf-migrate exits %d" % (name, want_rc), rc == want_rc,
               "exit %d" % rc, err)
    if rc not in (0, 3):
        raise M.L.RunError(name)
    frames = []
    for tag, text, exe in (("stock", deck, s.args.lmp), ("rigid", out, None)):
        s.run("%s_%s" % (name, tag), text, exe=exe)
        os.replace(s.path(dump), s.path("%s_%s.dump" % (name, tag)))
        frames.append(M.read_dump(s.path("%s_%s.dump" % (name, tag))))
    return frames[0], frames[1], err, out

