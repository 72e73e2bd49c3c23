#!/bin/sh
# Runs tachyon-nox on a copy of the scene ($1) without its cylinders (FCYLINDER
# and their RING caps): check_silhouettes.py must notice the missing geometry.
set -e
scene="$1"
shift
grep -v -e '^FCYLINDER' -e '^RING' "$scene" > "$scene.without_cylinders.dat"
exec tachyon-nox "$scene.without_cylinders.dat" "$@"
