# bash completion for jtracer-cli, jtracer-view, jtracer-mpi and jtracer-merge:
# their options, .jts scenes, images, the scene's camera names after --camera
# (asked of `jtracer-cli --list-cameras SCENE`) and the names it defines after
# --define, as NAME= (`jtracer-cli --list-defines SCENE`). Installed under each
# program's name, as bash-completion loads completions/<program> on demand.
# tests/install/completion_test.sh keeps the option lists equal to --help's.

# Files matching the extended glob $1 (e.g. '*.@(jts|JTS)') and directories.
_jtracer_files() {
    local IFS=$'\n'
    compopt -o filenames 2>/dev/null
    COMPREPLY+=($(compgen -f -X "!$1" -- "$cur") $(compgen -d -- "$cur"))
}

# What `jtracer-cli $2 SCENE` lists for the first .jts file on the command
# line ($1: the program being completed), each one matching $cur, with $3
# after it: the scene's cameras, or the names it defines.
_jtracer_scene_names() {
    local word scene= lister=jtracer-cli name typed
    for word in "${COMP_WORDS[@]:1}"; do
        if [[ $word == *.jts ]]; then
            scene=$word
            break
        fi
    done
    [[ -n $scene ]] || return
    scene=${scene/#\~/$HOME}
    # The jtracer-cli beside the program being completed, when typed with a path.
    [[ $1 == */* ]] && lister=${1%/*}/jtracer-cli
    typed=${cur//\\/}
    typed=${typed#[\"\']}
    while IFS= read -r name; do
        [[ $name == "$typed"* ]] && COMPREPLY+=("$(printf '%q' "$name")${3-}")
    done < <("$lister" "$2" "$scene" 2>/dev/null)
}

_jtracer() {
    local cur=${COMP_WORDS[COMP_CWORD]} prev=
    ((COMP_CWORD > 0)) && prev=${COMP_WORDS[COMP_CWORD - 1]}
    COMPREPLY=()
    local program=${1##*/} options positional='*.@(jts|JTS)'
    shopt -s extglob
    case $program in
    jtracer-cli)
        if [[ ${COMP_WORDS[1]} == diff ]] && ((COMP_CWORD > 1)); then
            program=jtracer-cli-diff
            options='-h --help -o --output --threshold --max-pixels --json --junit -q --quiet'
            positional='*.@(bmp|BMP|png|PNG)'
        elif [[ ${COMP_WORDS[1]} == info ]] && ((COMP_CWORD > 1)); then
            program=jtracer-cli-info
            options='-h --help --json --define --clock'
        else
            options='-h --help --version -o --output --camera --width --height --samples
                --threads -q --quiet --progress --region --region-output --check --expect --threshold
                --max-pixels --update --junit --define --clock --frames --frame-range --skip-existing'
        fi
        ;;
    jtracer-mpi)
        options='-h --help --version -o --output --camera --width --height --samples --threads
            -q --quiet --progress --tile-size --rank-timeout --stats --define --clock --frames
            --frame-range --skip-existing --region --region-output --check'
        ;;
    jtracer-merge)
        options='-h --help --version -o --output -q --quiet'
        positional='*.@(bmp|BMP)'
        ;;
    jtracer-view)
        options='-h --help --version --define --clock --screenshot --save-render --size
            --exit-when-done --timeout'
        ;;
    *) return ;;
    esac

    case $prev in
    -o | --output)
        if [[ $program == jtracer-cli-diff ]]; then
            _jtracer_files '*.@(png|PNG)'
        else
            _jtracer_files '*.@(bmp|BMP|png|PNG)'
        fi
        return
        ;;
    --screenshot)
        _jtracer_files '*.@(png|PNG)'
        return
        ;;
    --expect | --save-render)
        _jtracer_files '*.@(bmp|BMP|png|PNG)'
        return
        ;;
    --junit)
        _jtracer_files '*.@(xml|XML)'
        return
        ;;
    --camera)
        _jtracer_scene_names "$1" --list-cameras
        return
        ;;
    --progress)
        COMPREPLY=($(compgen -W 'auto bar log none' -- "$cur"))
        return
        ;;
    --width | --height | --samples | --threads | --region | --threshold | --max-pixels | \
        --tile-size | --rank-timeout | --size | --timeout | --clock | --frames | --frame-range)
        return # a number or a list of numbers: nothing to offer
        ;;
    --define)
        # NAME= for the names the scene defines; the value is the user's.
        [[ $cur == *=* ]] && return
        compopt -o nospace 2>/dev/null
        _jtracer_scene_names "$1" --list-defines =
        return
        ;;
    esac

    if [[ $cur == -* ]]; then
        COMPREPLY=($(compgen -W "$options" -- "$cur"))
        return
    fi
    if [[ $program == jtracer-cli && $COMP_CWORD == 1 ]]; then
        local command
        for command in diff info; do
            [[ $command == "$cur"* ]] && COMPREPLY+=("$command")
        done
    fi
    _jtracer_files "$positional"
}

complete -F _jtracer jtracer-cli jtracer-view jtracer-mpi jtracer-merge
