#!/usr/bin/env bash
# Tests JTracer as users get it, from a finished build (default build/release):
#  1. `cmake --install` to a temporary prefix, moved elsewhere afterwards: every
#     file in place, nothing naming the source or build tree, the programs,
#     man pages, completions, desktop entry, MIME type, CMake package and
#     pkg-config file and Python module all working from the moved copy, and
#     the model reader module found by each of them;
#  2. `cpack -G DEB`: jtracer_<version>_amd64.deb with its Depends, installed
#     with dpkg, used (version, showcase render, man -w, import jtracer), and
#     removed cleanly.
# Step 2 needs root or sudo, like scripts/install-deps.sh; JT_SKIP_DEB=1 skips it.
set -euo pipefail
cd "$(dirname "$0")/.."
source=$(pwd)
build=$(cd "${1:-build/release}" && pwd)
version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
step() { echo "== install-test (${SECONDS}s): $*"; }
fail() {
    echo "install-test: FAIL: $*" >&2
    exit 1
}
# The reference images tests/render/reference_images_test.cpp renders at 160x90;
# mesh.jts reads a model file, through the model reader module.
reference=$source/tests/references/showcase.png
mesh_reference=$source/tests/references/mesh.png

# --- 1. cmake --install ---------------------------------------------------
step "cmake --install to a temporary prefix"
cmake --install "$build" --prefix "$work/staged" >/dev/null
# Moving the tree proves that nothing in it depends on where it was put.
mv "$work/staged" "$work/prefix"
prefix=$work/prefix
libdir=$(dirname "$(find "$prefix" -name libjtracer_scene.a)")
for file in bin/jtracer-cli bin/jtracer-merge share/jtracer/scenes/showcase.jts \
    share/jtracer/scenes/manual/sphere.jts share/jtracer/scenes/mesh.jts \
    share/man/man1/jtracer-cli.1.gz \
    share/man/man1/jtracer-merge.1.gz share/man/man5/jts.5.gz \
    share/bash-completion/completions/jtracer-cli share/mime/packages/jtracer.xml \
    include/jtracer/version.hpp include/jtracer/render_job.hpp; do
    [ -e "$prefix/$file" ] || fail "cmake --install did not install $file"
done
# The Python module, where Debian's python3 looks for the prefix's modules.
python_dir=$(sed -n 's/^JT_PYTHON_INSTALL_DIR:STRING=//p' "$build/CMakeCache.txt")
if [ -n "$python_dir" ]; then
    for file in "$python_dir"/jtracer.pyi "$python_dir"/jtracer.cpython-*.so; do
        compgen -G "$prefix/$file" >/dev/null || fail "cmake --install did not install $file"
    done
fi
[ -f "$libdir/cmake/JTracer/JTracerConfig.cmake" ] || fail "no JTracerConfig.cmake"
[ -f "$libdir/pkgconfig/jtracer.pc" ] || fail "no jtracer.pc"
model_reader=${libdir#"$prefix"/}/jtracer/modules/libjtracer_model_reader.so
[ -f "$prefix/$model_reader" ] || fail "cmake --install did not install $model_reader"
with_viewer=0
if [ -e "$prefix/bin/jtracer-view" ]; then
    with_viewer=1
    for file in share/man/man1/jtracer-view.1.gz share/applications/jtracer-view.desktop \
        share/icons/hicolor/128x128/apps/jtracer.png share/bash-completion/completions/jtracer-view; do
        [ -e "$prefix/$file" ] || fail "cmake --install did not install $file"
    done
fi

step "nothing installed names the source or build tree"
for tree in "$source" "$build"; do
    if found=$(grep -rlaF -- "$tree" "$prefix"); then
        fail "these installed files name $tree: $found"
    fi
done

step "the installed programs render the installed showcase"
"$prefix/bin/jtracer-cli" --version
"$prefix/bin/jtracer-cli" -q "$prefix/share/jtracer/scenes/showcase.jts" -o "$work/showcase.png" --width 160 --height 90 \
    --expect "$reference"
"$prefix/bin/jtracer-cli" -q "$prefix/share/jtracer/scenes/mesh.jts" -o "$work/mesh.png" --width 160 --height 90 \
    --expect "$mesh_reference"
if [ "$with_viewer" = 1 ]; then
    # No scene given: the viewer opens the showcase beside its own bin/.
    (cd "$work" && "$prefix/bin/jtracer-view" --screenshot view.png --size 320x200 --timeout 120) \
        2>"$work/view.err" || fail "jtracer-view without a scene: $(cat "$work/view.err")"
    grep -q 'wrote view.png' "$work/view.err" || fail "jtracer-view: $(cat "$work/view.err")"
    ! grep -qi 'error\|cannot' "$work/view.err" || fail "jtracer-view: $(cat "$work/view.err")"
fi

# The module renders an installed scene to the installed jtracer-cli's BMP
# pixels (and the reference's), from the copy PYTHONPATH names. Debian's
# python3: the module is built for it and uses its numpy.
check_python_module() { # PYTHON_DIR SCENE CLI REFERENCE
    /usr/bin/python3 - "$1" "$2" "$3" "$4" "$work" <<'PYTHON'
import pathlib, subprocess, sys
python_dir, scene_path, cli, reference, work = sys.argv[1:]
import jtracer
where = pathlib.Path(jtracer.__file__).resolve()
assert where.parent == pathlib.Path(python_dir).resolve(), f"imported {where}, not from {python_dir}"
image = jtracer.load(scene_path).render(width=160, height=90)
bmp = pathlib.Path(work) / "module-cli.bmp"
subprocess.run([cli, "-q", scene_path, "-o", str(bmp), "--width", "160", "--height", "90"], check=True)
assert (jtracer.read_image(bmp) == image).all(), "the module's render differs from jtracer-cli's"
difference = jtracer.diff(reference, image)
assert difference.same_size and difference.pixels_over == 0, difference
version = subprocess.run([cli, "--version"], capture_output=True, text=True, check=True).stdout
assert version.split()[1] == jtracer.__version__, (version, jtracer.__version__)
print(f"jtracer {jtracer.__version__} from {where}: {pathlib.Path(scene_path).name} matches jtracer-cli's pixels")
PYTHON
}
if [ -n "$python_dir" ]; then
    step "the installed Python module renders the installed showcase and mesh scene"
    for scene in showcase mesh; do
        PYTHONPATH=$prefix/$python_dir check_python_module "$prefix/$python_dir" \
            "$prefix/share/jtracer/scenes/$scene.jts" "$prefix/bin/jtracer-cli" \
            "$source/tests/references/$scene.png"
    done
fi

step "the CI script of docs/ci.md, with the installed jtracer-cli"
mkdir -p "$work/project/scenes"
cp "$prefix/share/jtracer/scenes/manual/sphere.jts" "$prefix/share/jtracer/scenes/manual/plane.jts" \
    "$work/project/scenes/"
sed -n '/^## A plain shell script/,/^## /p' "$source/docs/ci.md" | sed -n '/^```sh$/,/^```$/p' |
    sed '1d;$d' >"$work/project/check-renders.sh"
(
    cd "$work/project"
    export PATH=$prefix/bin:$PATH
    UPDATE=1 sh check-renders.sh
    [ -f references/sphere.png ] || fail "check-renders.sh UPDATE=1 made no references"
    sh check-renders.sh >/dev/null || fail "check-renders.sh fails on its own references"
    jtracer-cli -q scenes/plane.jts -o references/sphere.png
    if sh check-renders.sh >/dev/null 2>&1; then fail "check-renders.sh passes a wrong reference"; fi
    [ -f out/sphere.diff.png ] || fail "check-renders.sh left no heat map"
)

step "man pages, completions, desktop entry and MIME type"
found=$(MANPATH=$prefix/share/man man -w jtracer-cli)
[ "$found" = "$prefix/share/man/man1/jtracer-cli.1.gz" ] || fail "man -w jtracer-cli: '$found'"
MANPATH=$prefix/share/man MANWIDTH=80 man --warnings jtracer-cli 2>"$work/man.err" >/dev/null
[ ! -s "$work/man.err" ] || fail "man --warnings jtracer-cli: $(cat "$work/man.err")"
# bash-completion's own loader finds the installed completion by program name.
loaded=$(XDG_DATA_DIRS=$prefix/share bash -c 'source /usr/share/bash-completion/bash_completion
    __load_completion jtracer-cli && complete -p jtracer-cli')
[ "$loaded" = "complete -F _jtracer jtracer-cli" ] || fail "bash-completion loaded: '$loaded'"
if [ "$with_viewer" = 1 ]; then
    desktop-file-validate "$prefix/share/applications/jtracer-view.desktop"
fi
cp -r "$prefix/share/mime" "$work/mime"
update-mime-database "$work/mime" >/dev/null 2>&1 # it notes that the folder is not in XDG_DATA_DIRS
grep -q '^50:text/x-jtracer-scene:\*\.jts$' "$work/mime/globs2" ||
    fail "the MIME database does not map *.jts to text/x-jtracer-scene"

step "a program outside the tree embeds the renderer (CMake package, pkg-config)"
cmake -S "$source/tests/install/consumer" -B "$work/consumer" -G Ninja \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/consumer" >/dev/null
"$work/consumer/consumer"
# shellcheck disable=SC2046 # pkg-config's flags are words
g++ -std=c++20 -O1 -o "$work/consumer-pc" "$source/tests/install/consumer/consumer.cpp" \
    $(PKG_CONFIG_PATH=$libdir/pkgconfig pkg-config --cflags --libs jtracer)
"$work/consumer-pc"

# --- 2. the Debian package ------------------------------------------------
if [ "${JT_SKIP_DEB:-0}" = 1 ]; then
    echo "install-test: JT_SKIP_DEB=1: the .deb is not tested"
    exit 0
fi
step "cpack -G DEB"
(cd "$build" && cpack -G DEB -B "$work/deb" >/dev/null)
deb=$work/deb/jtracer_${version}_amd64.deb
[ -f "$deb" ] || fail "cpack made no $(basename "$deb"): $(ls "$work/deb")"
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
grep -q 'libtbb' <<<"$depends" || fail "Depends lacks the TBB library: $depends"
if [ -n "$python_dir" ]; then
    suggests=$(dpkg-deb -f "$deb" Suggests)
    grep -q 'python3-numpy' <<<"$suggests" || fail "Suggests lacks python3-numpy: $suggests"
fi
contents=$(dpkg-deb -c "$deb")
if grep -q '/usr/local/' <<<"$contents"; then fail "the .deb installs under /usr/local"; fi
grep -q " ./usr/$model_reader\$" <<<"$contents" || fail "the .deb lacks /usr/$model_reader"

sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
dpkg-query -W jtracer >/dev/null 2>&1 && fail "a jtracer package is already installed"
step "dpkg -i $(basename "$deb")"
# Container images often tell dpkg to leave out man pages: ours must go in.
"${sudo_cmd[@]}" dpkg --path-include='/usr/share/man/*/jt*' -i "$deb" >/dev/null
removed=0
remove() {
    [ "$removed" = 1 ] || "${sudo_cmd[@]}" dpkg -r jtracer >/dev/null
    removed=1
}
trap 'remove; rm -rf "$work"' EXIT
[ "$(command -v jtracer-cli)" = /usr/bin/jtracer-cli ] || fail "jtracer-cli is not /usr/bin's"
/usr/bin/jtracer-cli --version
/usr/bin/jtracer-cli -q /usr/share/jtracer/scenes/showcase.jts -o "$work/deb-showcase.png" --width 160 --height 90 \
    --expect "$reference"
/usr/bin/jtracer-cli -q /usr/share/jtracer/scenes/mesh.jts -o "$work/deb-mesh.png" --width 160 --height 90 \
    --expect "$mesh_reference"
found=$(man -w jtracer-cli)
[ "$found" = /usr/share/man/man1/jtracer-cli.1.gz ] || fail "man -w jtracer-cli: '$found'"
if [ -n "$python_dir" ]; then
    step "python3 imports the .deb's module without PYTHONPATH"
    for scene in showcase mesh; do
        (unset PYTHONPATH && cd "$work" && check_python_module "/usr/$python_dir" \
            "/usr/share/jtracer/scenes/$scene.jts" /usr/bin/jtracer-cli \
            "$source/tests/references/$scene.png")
    done
fi
step "dpkg -r jtracer"
remove
[ ! -e /usr/bin/jtracer-cli ] || fail "dpkg -r left /usr/bin/jtracer-cli"
[ ! -e /usr/share/jtracer ] || fail "dpkg -r left /usr/share/jtracer"
[ ! -e "/usr/$model_reader" ] || fail "dpkg -r left /usr/$model_reader"
if [ -n "$python_dir" ] && compgen -G "/usr/$python_dir/jtracer*" >/dev/null; then
    fail "dpkg -r left the Python module in /usr/$python_dir"
fi
status=$(dpkg-query -W -f='${Status}' jtracer 2>/dev/null || true)
# Nothing left for a purge either: no conffiles, no maintainer scripts.
if [ -n "$status" ]; then fail "dpkg -r left jtracer in dpkg's records: $status"; fi
echo "install-test: all passed in ${SECONDS}s"
