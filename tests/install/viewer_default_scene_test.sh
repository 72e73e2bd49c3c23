#!/usr/bin/env bash
# jtracer-view without a scene opens the showcase found from its own folder
# (../share/jtracer/scenes/showcase.jts: installed, or the build tree's link),
# from any working folder.
# Usage: viewer_default_scene_test.sh VIEW
set -euo pipefail
source "$(dirname "$0")/help_options.sh"
view=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$view" --screenshot shot.png --size 160x120 --timeout 120 2>err.txt || fail "$(cat err.txt)"
grep -q 'wrote shot.png' err.txt || fail "$(cat err.txt)"
[ -s shot.png ] || fail "no screenshot"
echo "jtracer-view without a scene: opened the showcase, wrote the screenshot"
