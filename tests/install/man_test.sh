#!/usr/bin/env bash
# The manual pages: clean under `mandoc -T lint`, every option of every
# program's --help documented in its page, and jts(5)'s example a valid scene.
# Usage: man_test.sh MAN_DIR CLI MERGE [VIEW] [MPI]
set -euo pipefail
source "$(dirname "$0")/help_options.sh"
man_dir=$1 cli=$2 merge=$3 view=${4:-} mpi=${5:-}

for page in "$man_dir"/*.[15]; do
    # STYLE notes (such as cross references to pages not installed here) are fine.
    lint=$(mandoc -T lint -W warning "$page" 2>&1) || fail "mandoc -T lint $page: $lint"
done

# Every option --help shows appears in the page as "Fl name".
check_page() {
    local page=$1
    shift
    local option count=0
    while read -r option; do
        grep -qF -- "Fl ${option#-}" "$page" || grep -qF -- "Fl \\${option#-}" "$page" ||
            fail "$* --help lists $option, $(basename "$page") does not document it"
        count=$((count + 1))
    done < <(help_options "$@")
    [ "$count" -ge 3 ] || fail "$* --help: found only $count options"
}
check_page "$man_dir/jtracer-cli.1" "$cli"
check_page "$man_dir/jtracer-cli.1" "$cli" diff
check_page "$man_dir/jtracer-cli.1" "$cli" info
check_page "$man_dir/jtracer-merge.1" "$merge"
[ -z "$view" ] || check_page "$man_dir/jtracer-view.1" "$view"
[ -z "$mpi" ] || check_page "$man_dir/jtracer-mpi.1" "$mpi"

# And the other way round: every option a page documents exists.
check_documented() {
    local page=$1 real=$2 option
    while read -r option; do
        grep -qxF -- "$option" <<<"$real" ||
            fail "$(basename "$page") documents $option, which the program does not have"
    done < <(grep -oE '(^\.| )Fl (\\-)?[a-z][a-z-]*' "$page" |
        sed -E 's/.*Fl //; s/^\\-/--/; s/^([a-z])$/-\1/' | sort -u)
}
check_documented "$man_dir/jtracer-cli.1" "$(help_options "$cli"; help_options "$cli" diff; help_options "$cli" info)"
check_documented "$man_dir/jtracer-merge.1" "$(help_options "$merge")"
[ -z "$view" ] || check_documented "$man_dir/jtracer-view.1" "$(help_options "$view")"
[ -z "$mpi" ] || check_documented "$man_dir/jtracer-mpi.1" "$(help_options "$mpi")"

# The hidden option stays out of the manual as it stays out of --help.
! grep -q 'list-cameras' "$man_dir/jtracer-cli.1" || fail "jtracer-cli.1 documents --list-cameras"

# The example of jts(5) is a scene without errors.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed -n '/^\.Sh EXAMPLES/,/^\.Sh/p' "$man_dir/jts.5" | sed -n '/^\.Bd -literal/,/^\.Ed/p' |
    sed '1d;$d' >"$work/example.jts"
[ -s "$work/example.jts" ] || fail "no example in jts.5"
"$cli" --check "$work/example.jts" || fail "the example of jts(5) has errors"
echo "man pages: lint clean, every option documented, jts(5) example valid"
