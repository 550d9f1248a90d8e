"""rigidsurf-build-law: builds a VUINTER written as for Abaqus into a library that
exports vuinter_ and links librigidsurf_abaqus; its usage and compile errors; the
compiler's warnings printed as the compiler gave them, with their count.

    test_build_law_cli.py PATH/rigidsurf-build-law PATH/vuinter_util.f
"""
import os
import shutil
import subprocess
import sys
import tempfile

exe, routine = sys.argv[1], sys.argv[2]
failed = 0


def check(name, cond, detail=""):
    global failed
    print(("ok   " if cond else "FAIL ") + name + (": " + detail if detail and not cond else ""))
    failed += 0 if cond else 1


def run(args, cwd):
    p = subprocess.run([exe] + args, cwd=cwd, capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


tmp = tempfile.mkdtemp(prefix="rs_build_law_")
try:
    shutil.copy(routine, os.path.join(tmp, "mylaw.f"))
    # default output name, and -v prints the compiler command
    rc, out, err = run(["-v", "mylaw.f"], tmp)
    lib = os.path.join(tmp, "libmylaw.so")
    check("builds libmylaw.so", rc == 0 and os.path.isfile(lib), err)
    check("-v prints the gfortran command with 132 columns and the includes",
          "-ffixed-line-length-132" in out and "-fallow-argument-mismatch" in out
          and "-lrigidsurf_abaqus" in out, out)
    if rc == 0:
        syms = subprocess.run(["nm", "-D", "--defined-only", lib], capture_output=True,
                              text=True).stdout
        check("exports vuinter_", " vuinter_" in syms, syms)
        undef = subprocess.run(["nm", "-D", "--undefined-only", lib], capture_output=True,
                               text=True).stdout
        check("calls the utility routines", "xplb_abqerr_" in undef and "vgetpartinfo_" in undef,
              undef)
        ldd = subprocess.run(["ldd", lib], capture_output=True, text=True).stdout
        check("links librigidsurf_abaqus and finds it", "librigidsurf_abaqus.so" in ldd
              and "not found" not in ldd, ldd)
    # -o
    rc, out, err = run(["mylaw.f", "-o", "sub/other.so"], tmp)
    check("-o into a missing folder fails with the path", rc == 1 and "sub/other.so" in err, err)
    os.mkdir(os.path.join(tmp, "sub"))
    rc, out, err = run(["mylaw.f", "-o", "sub/other.so"], tmp)
    check("-o names the library", rc == 0 and os.path.isfile(os.path.join(tmp, "sub/other.so")),
          err)
    # a compile error: the file, the line, the compiler's message, the log
    with open(os.path.join(tmp, "broken.f"), "w") as f:
        f.write("      SUBROUTINE VUINTER(X)\n      INCLUDE 'VABA_PARAM.INC'\n"
                "      X = = 1.0D0\n      END\n")
    rc, out, err = run(["broken.f"], tmp)
    check("a compile error exits 1", rc == 1, "exit %d" % rc)
    check("and names file, line and message", "broken.f:3:" in err and "Error" in err, err)
    check("and leaves no library", not os.path.exists(os.path.join(tmp, "libbroken.so")))
    check("and keeps the compiler output", os.path.isfile(os.path.join(tmp, "libbroken.so.log")))
    # warnings: line 5, a REAL DO variable (a deleted feature); line 8, a REAL index
    with open(os.path.join(tmp, "warns.f"), "w") as f:
        f.write("      SUBROUTINE VUINTER(STRESS, PROPS)\n      INCLUDE 'VABA_PARAM.INC'\n"
                "      DIMENSION PROPS(3)\n      S = 0.D0\n      DO R = 1, 3\n"
                "        S = S + R\n      END DO\n      STRESS = PROPS(S / 6.D0)\n"
                "      END\n")
    rc, out, err = run(["warns.f"], tmp)
    check("a build with warnings succeeds",
          rc == 0 and os.path.isfile(os.path.join(tmp, "libwarns.so")), err)
    check("and prints the compiler's warnings as it gave them",
          "warns.f:5:" in err and "Warning: Deleted feature: Loop variable" in err
          and "warns.f:8:" in err and "Warning: Legacy Extension: REAL array index" in err
          and "DO R = 1, 3" in err, err)
    check("and their count and the log",
          "warns.f: 2 warnings from the compiler (whole output: libwarns.so.log)" in err, err)
    check("stdout holds the library only", out == "libwarns.so\n", out)
    with open(os.path.join(tmp, "clean.f"), "w") as f:
        f.write("      SUBROUTINE VUINTER(X)\n      X = 1.0D0\n      END\n")
    rc, out, err = run(["clean.f"], tmp)
    check("a build without warnings prints the library only",
          rc == 0 and err == "" and out == "libclean.so\n", out + err)
    # usage errors
    for args, what in (([], "no file"), (["-o"], "-o without a name"),
                       (["--bogus", "mylaw.f"], "an unknown option"),
                       (["a.f", "b.f"], "two files")):
        rc, out, err = run(args, tmp)
        check("usage error: " + what, rc == 2 and err.strip() != "", "exit %d %s" % (rc, err))
    rc, out, err = run(["mylaw.c"], tmp)
    check("not a Fortran file", rc == 1 and "not a Fortran source" in err, err)
    rc, out, err = run(["absent.f"], tmp)
    check("a missing file", rc == 1 and "absent.f: cannot read" in err, err)
finally:
    shutil.rmtree(tmp, ignore_errors=True)

print("%s" % ("FAILED" if failed else "all passed"))
sys.exit(1 if failed else 0)
