#!/usr/bin/env bash
# The shell completions: bash registers one function for every program, offers
# exactly the options of each program's --help, completes scenes, images and
# the scene's camera names (through `jtracer-cli --list-cameras`); zsh loads
# its completion for every program and names every option.
# Usage: completion_test.sh COMPLETIONS_DIR CLI MERGE [VIEW] [MPI]
set -euo pipefail
source "$(dirname "$0")/help_options.sh"
completions=$(cd "$1" && pwd) cli=$2 merge=$3 view=${4:-} mpi=${5:-}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
cat >scene.jts <<'SCENE'
define radius = 1;
define red = <1, 0, 0>;
material shiny { reflection: 0.5; }
render_settings { width: 8; height: 8; }
cameras {
    perspective_camera { name: "Main"; position: <0, 1, 5>; }
    perspective_camera { name: "High Angle"; position: <0, 6, 1>; look_at: <0, 0, 0>; }
}
SCENE
touch other.jts notes.txt part1.bmp part2.png ref.png
mkdir folder

source "$completions/jtracer.bash"
for program in jtracer-cli jtracer-merge jtracer-view jtracer-mpi; do
    [ "$(complete -p "$program")" = "complete -F _jtracer $program" ] ||
        fail "complete -p $program: $(complete -p "$program" 2>&1)"
done

# Completes word CWORD (default the last) of "$@" as bash would, and prints
# the candidates one a line, sorted.
complete_line() {
    COMP_WORDS=("$@")
    COMP_CWORD=${CWORD:-$((${#COMP_WORDS[@]} - 1))}
    COMP_LINE="$*"
    COMP_POINT=${#COMP_LINE}
    COMPREPLY=()
    _jtracer "${COMP_WORDS[0]}" "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD - 1]:-}"
    printf '%s\n' "${COMPREPLY[@]}" | sort
}
expect() {
    local want=$1 got
    shift
    got=$(complete_line "$@")
    [ "$got" = "$want" ] || fail "completing '$*': got [$(echo $got)], want [$(echo $want)]"
}

# Every option of --help, and nothing else (the hidden --list-cameras is not offered).
same_options() {
    local program=$1
    shift
    local got want
    got=$(complete_line "$program" "$@" - | sort -u)
    want=$(help_options "${tools[$program]}" "$@")
    [ "$got" = "$want" ] ||
        fail "$program $*: completion offers [$(echo $got)], --help lists [$(echo $want)]"
}
declare -A tools=([jtracer-cli]=$cli [jtracer-merge]=$merge)
[ -z "$view" ] || tools[jtracer-view]=$view
[ -z "$mpi" ] || tools[jtracer-mpi]=$mpi
for program in "${!tools[@]}"; do same_options "$program"; done
same_options jtracer-cli diff
same_options jtracer-cli info

expect --camera jtracer-cli --cam
expect $'--max-pixels' jtracer-cli --max
# Scenes and folders, not other files; "diff" and "info" only as the first word.
expect $'diff\nfolder\ninfo\nother.jts\nscene.jts' jtracer-cli ''
expect $'scene.jts' jtracer-cli sc
expect $'diff' jtracer-cli d
expect $'info' jtracer-cli i
# info takes a scene.
expect $'scene.jts' jtracer-cli info sc
expect $'--json' jtracer-cli info --j
expect '' jtracer-cli scene.jts d
# diff takes images; -o an image.
expect $'part1.bmp\npart2.png' jtracer-cli diff part
expect $'folder\npart2.png\nref.png' jtracer-cli diff a.png -o ''
expect $'part1.bmp' jtracer-merge -o frame.png part
expect $'folder\npart2.png\nref.png' jtracer-view --screenshot ''
expect '' jtracer-cli scene.jts --width ''

# Camera names, from the scene on the line, through the jtracer-cli on PATH or
# the one beside the program as typed; a name with a space comes quoted.
cameras=$'High\\ Angle\nMain'
PATH=$(dirname "$cli"):$PATH expect "$cameras" jtracer-cli scene.jts --camera ''
expect "$cameras" "$cli" scene.jts --camera ''
CWORD=2 expect 'High\ Angle' "$cli" --camera H scene.jts
expect 'Main' "$cli" scene.jts --camera M
PATH=$(dirname "$cli"):$PATH expect "$cameras" jtracer-mpi scene.jts --camera ''
expect '' "$cli" --camera ''

# --define offers NAME= for each name the scene defines (not its materials),
# for the three programs that take it; the value is the user's.
defines=$'radius=\nred='
PATH=$(dirname "$cli"):$PATH expect "$defines" jtracer-cli scene.jts --define ''
expect "$defines" "$cli" scene.jts --define ''
expect 'red=' "$cli" scene.jts --define re
CWORD=2 expect 'radius=' "$cli" --define ra scene.jts
PATH=$(dirname "$cli"):$PATH expect "$defines" jtracer-view scene.jts --define ''
PATH=$(dirname "$cli"):$PATH expect "$defines" jtracer-mpi scene.jts --define ''
expect '' "$cli" scene.jts --define 'radius=2'
expect '' "$cli" --define ''

# zsh: the completion loads for every program and names every option.
if command -v zsh >/dev/null; then
    registered=$(HOME=$work zsh -f -c "fpath=('$completions' \$fpath); autoload -U compinit
        compinit -u -D; print -r -- \$_comps[jtracer-cli] \$_comps[jtracer-merge] \
        \$_comps[jtracer-view] \$_comps[jtracer-mpi]")
    [ "$registered" = "_jtracer _jtracer _jtracer _jtracer" ] || fail "zsh registered: $registered"
    for program in "${!tools[@]}"; do
        for option in $(help_options "${tools[$program]}"); do
            grep -qE -- "(\\{|'|\\)|,|\\*)$option[],[}]" "$completions/_jtracer" ||
                fail "_jtracer (zsh) lacks $option of $program"
        done
    done
else
    fail "zsh is not installed (scripts/install-deps.sh installs it)"
fi
echo "completions: bash and zsh complete every option, scenes, images and cameras"
