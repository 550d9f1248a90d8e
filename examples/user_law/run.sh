#!/bin/bash
# User laws: bash examples/user_law/run.sh
# Builds liggghts-rigidsurf in build/ (or $BUILD_DIR) when needed, builds the C law
# (mylaw.c -> libmylaw.so) into examples/user_law/out/, runs in.slide with the built-in
# law `coulomb`, with `law user ./libmylaw.so my_coulomb` and with
# `law vuinter ../myvuinter.f` (the fix compiles the Fortran source itself), and
# compares the three runs with each other and with the closed forms.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
# The user's side for the C law: a plain compiler call against the public header.
gcc -O2 -Wall -Wextra -Werror -shared -fPIC -I"$root/include" "$here/mylaw.c" -o libmylaw.so
echo "user_law: 8 spheres on a 30 degree incline, 0.25 s, three times (built-in, C, VUINTER)"
for law in builtin c vuinter; do
    NP=1 rs_run "$law" ../in.slide -var law "$law"
done
/usr/bin/python3 "$here/compare.py" "$out"
echo "wall time: $(( $(date +%s) - start )) s"
