#!/usr/bin/env bash
# Renders one small picture of every example scene into docs/images/ and
# writes docs/gallery.md around them. Not run by CI: rerun it after changing
# a scene or the renderer, look at the pictures, and commit them.
# Usage: scripts/gallery.sh [BUILD_DIR]   (default build/release, already built)
set -euo pipefail
cd "$(dirname "$0")/.."
cli=${1:-build/release}/cli/jtracer-cli
[ -x "$cli" ] || { echo "gallery: no $cli: build first (README, Set-up)" >&2; exit 2; }
mkdir -p docs/images

# A picture's width, and the height that keeps the scene's own aspect.
gallery_width=320

{
    echo "# Gallery"
    echo
    echo "One picture of every example scene in \`scenes/\` (installed in"
    echo "\`share/jtracer/scenes/\`), ${gallery_width} pixels wide, rendered by \`scripts/gallery.sh\`."
    echo "Each comes with the command that renders it at the scene's own size. The manual's"
    echo "examples that give no material render black, as the language's defaults say: their"
    echo "scenes add a background so that the shape shows as a silhouette."
    # The showcase first, the other scenes, then the manual's examples; orbit.jts,
    # an animation, gets a contact sheet below.
    for scene in scenes/showcase.jts $(ls scenes/*.jts scenes/*/main.jts |
        grep -v -e '^scenes/showcase.jts$' -e '^scenes/orbit.jts$') scenes/manual/*.jts; do
        # Named as tests/references/ names it: the path's folders joined with _.
        name=$(echo "${scene#scenes/}" | sed 's/\.jts$//; s#/#_#g')
        # The render_settings' width and height (the first two integer sizes).
        read -r width height <<<"$(sed -n 's/^ *\(width\|height\): *\([0-9]*\);.*/\2/p' "$scene" |
            head -2 | tr '\n' ' ')"
        small_height=$((height * gallery_width / width))
        "$cli" -q "$scene" -o "docs/images/$name.png" --width "$gallery_width" \
            --height "$small_height"
        # The first sentence of the scene's opening comment.
        title=$(awk '/^#/ { sub(/^# */, ""); printf "%s ", $0; next } { exit }' "$scene" |
            sed 's/\([.]\)[[:space:]].*/\1/; s/[[:space:]]*$//')
        echo
        echo "## \`$scene\`"
        echo
        [ -z "$title" ] || { echo "$title"; echo; }
        echo "![$name](images/$name.png)"
        echo
        echo '```sh'
        echo "jtracer-cli $scene -o $name.png"
        echo '```'
    done
    # The animation: 48 small frames in one contact sheet (a second or two).
    frames=$(mktemp -d)
    trap 'rm -rf "$frames"' EXIT
    "$cli" -q scenes/orbit.jts --frames 48 --width 160 --height 90 -o "$frames/orbit-%02d.bmp"
    scripts/contact_sheet.py docs/images/orbit_sheet.png 8 "$frames"/orbit-*.bmp
    echo
    echo "## \`scenes/orbit.jts\` (48 frames)"
    echo
    echo "An animation driven by \`clock\`: the camera circles the scene once while the ball"
    echo "bounces twice. Frames 0 to 47, left to right and top to bottom, 160 pixels wide:"
    echo
    echo "![orbit](images/orbit_sheet.png)"
    echo
    echo '```sh'
    echo "jtracer-cli scenes/orbit.jts --frames 48 -o orbit-%04d.png"
    echo '```'
} >docs/gallery.md.new
mv docs/gallery.md.new docs/gallery.md
echo "gallery: wrote docs/gallery.md and $(ls docs/images/*.png | wc -l) pictures in docs/images/"
